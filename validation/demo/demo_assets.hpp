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
  std::string basis;           ///< a .U file (weights beside it); "" : computed and cached
  /// What to compute when no basis file is given: "modal" (modal analysis, r modes) or
  /// "polynomial" (the first r polynomial modes, stiffness-scaled).
  std::string basis_kind = "modal";
  int modes = 30;
  ElasticMaterial material;
  std::string cache_dir;
  bool fresh_certificates = false;     ///< precompute even when the cached file is valid
  std::string scale;                   ///< "auto", a factor, or "" (as read) for the rest positions
  bool exclude_rest_contacts = false;  ///< ignore the pairs touching at rest (excluded_pairs.hpp)
};

struct DemoAssets {
  std::string name;  ///< for file names and reports
  std::unique_ptr<SubspaceModel> model;
  std::unique_ptr<SubspaceBvh> bvh;
  std::unique_ptr<Certificates> certificates;
  double basis_seconds = 0.0;        ///< 0 when read from the cache or a file
  double certificate_seconds = 0.0;  ///< 0 when read from the cache
};

DemoAssets load_demo_assets(const DemoAssetOptions& options, std::ostream& progress);

/// The repository's data directory (the shipped demo mesh).
std::string data_dir();

/// The bounding-box diagonal of the default bunny (data/bunny15k.off), in metres: the size
/// the scenes' materials and impulses are made for (mesh_units.hpp).
double default_bunny_diagonal();

}  // namespace sscc::validation
