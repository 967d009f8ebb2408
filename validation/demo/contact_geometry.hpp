// The contact points and normals of reported feature contacts are the library's
// (sscc/scene/contact_geometry.hpp); the demo's response uses them under these names.
#pragma once

#include "sscc/scene/contact_geometry.hpp"

namespace sscc::validation {

using sscc::contact_frame;
using sscc::contact_gap;
using sscc::ContactFrame;

}  // namespace sscc::validation
