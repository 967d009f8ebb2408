// The sscc library: continuous collision detection for deformable triangle meshes.
// This umbrella header includes the public API.
#pragma once

#include "sscc/basis/example_pose_generator.hpp"
#include "sscc/basis/example_poses.hpp"
#include "sscc/basis/key_points.hpp"
#include "sscc/bvh/subspace_bvh.hpp"
#include "sscc/ccd/ccd_types.hpp"
#include "sscc/ccd/kernels.hpp"
#include "sscc/certificates/certificates.hpp"
#include "sscc/certificates/triangle_pair_bound.hpp"
#include "sscc/geometry/triangle_distance.hpp"
#include "sscc/mesh/mesh_io.hpp"
#include "sscc/mesh/triangle_mesh.hpp"
#include "sscc/mesh/write_off.hpp"
#include "sscc/model/basis_io.hpp"
#include "sscc/model/polynomial_basis.hpp"
#include "sscc/model/subspace_model.hpp"
#include "sscc/prediction/cull_validation.hpp"
#include "sscc/prediction/culling_predictor.hpp"
#include "sscc/prediction/node_collisions.hpp"
#include "sscc/query/pose_step_ccd.hpp"
#include "sscc/query/self_ccd.hpp"
