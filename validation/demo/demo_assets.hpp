// What the demo needs before its first step: the mesh, its modal basis and the
// certificates, computed on first run and cached in a directory (a cached basis is tied
// to the mesh and the parameters by a key file; the certificate file checks itself and is
// recomputed when stale).
#pragma once

#include <memory>
#include <ostream>
#include <string>

#include "sscc/basis/linear_elasticity.hpp"
#include "sscc/certificates/certificates.hpp"
#include "sscc/model/subspace_model.hpp"

namespace sscc::validation {

struct DemoAssetOptions {
  std::string mesh;            ///< a mesh file, or "" for the generated or default one
  std::string generated_mesh;  ///< "spring": the double-helix spring; "": data/bunny15k.off
  std::string basis;           ///< a modal .U file (weights beside it); "" : computed and cached
  int modes = 30;
  ElasticMaterial material;
  std::string cache_dir;
};

struct DemoAssets {
  std::string name;  ///< for file names and reports
  std::unique_ptr<SubspaceModel> model;
  std::unique_ptr<SubspaceBvh> bvh;
  std::unique_ptr<Certificates> certificates;
};

DemoAssets load_demo_assets(const DemoAssetOptions& options, std::ostream& progress);

/// The repository's data directory (the shipped demo mesh).
std::string data_dir();

}  // namespace sscc::validation
