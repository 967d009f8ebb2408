#include "demo/demo_assets.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "basis_command.hpp"
#include "certificate_cache.hpp"
#include "demo/mesh_units.hpp"
#include "demo/spring_mesh.hpp"
#include "model_loading.hpp"
#include "sscc/basis/modal_analysis.hpp"
#include "sscc/common/timing.hpp"
#include "sscc/mesh/mesh_io.hpp"
#include "sscc/model/basis_io.hpp"

#ifndef SSCC_DATA_DIR
#define SSCC_DATA_DIR "data"
#endif

namespace sscc::validation {

namespace fs = std::filesystem;

std::string data_dir() { return SSCC_DATA_DIR; }

double default_bunny_diagonal() {
  static const double diagonal = read_mesh(data_dir() + "/bunny15k.off").bounding_box_diagonal();
  return diagonal;
}

namespace {

/// Identifies the mesh and the modal parameters a cached basis was made from.
std::string basis_key(const TriangleMesh& mesh, const DemoAssetOptions& o) {
  std::ostringstream text;
  text << std::hexfloat << mesh.vertex_count() << ' ' << mesh.triangle_count();
  for (const auto& p : mesh.vertices()) text << ' ' << p[0] << ' ' << p[1] << ' ' << p[2];
  for (const auto& t : mesh.triangles()) text << ' ' << t[0] << ' ' << t[1] << ' ' << t[2];
  std::ostringstream key;
  key << "sscc demo basis v1 mesh " << std::hash<std::string>{}(text.str()) << ' ' << o.basis_kind << " modes "
      << o.modes << " E " << o.material.youngs_modulus << " nu " << o.material.poisson_ratio << " rho "
      << o.material.density;
  return key.str();
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

DemoAssets load_demo_assets(const DemoAssetOptions& o, std::ostream& progress) {
  DemoAssets assets;
  TriangleMesh mesh = [&] {
    if (!o.mesh.empty()) {
      assets.name = fs::path(o.mesh).stem().string();
      return read_mesh(o.mesh);
    }
    if (o.generated_mesh == "spring") {
      assets.name = "spring";
      return double_helix_spring();
    }
    assets.name = "bunny15k";
    return read_mesh(data_dir() + "/bunny15k.off");
  }();
  progress << "demo: mesh " << assets.name << ": " << mesh.vertex_count() << " vertices, " << mesh.triangle_count()
           << " triangles\n";
  if (!o.scale.empty()) {
    const double factor = scale_factor(o.scale, mesh, default_bunny_diagonal());
    mesh = scaled(mesh, factor);
    progress << "demo: mesh scaled by " << factor << " (--scale " << o.scale << "): " << mesh.bounding_box_diagonal()
             << " m across\n";
  }
  if (!o.mesh.empty()) {
    if (const std::string warning = size_warning(mesh, default_bunny_diagonal()); !warning.empty())
      progress << "demo: " << warning << '\n';
  }
  Eigen::MatrixXd basis;
  Eigen::VectorXd weights;
  // Cached files are named by what they were made from, so that other materials or meshes
  // keep their own.
  const std::string key = o.basis.empty() ? basis_key(mesh, o) : "sscc demo basis file " + o.basis;
  char stem_text[512];
  std::snprintf(stem_text, sizeof stem_text, "%s/%s-%s%d-%016zx", o.cache_dir.c_str(), assets.name.c_str(),
                o.basis.empty() ? o.basis_kind.c_str() : "file", o.modes, std::hash<std::string>{}(key));
  const std::string stem = stem_text;
  if (!o.basis.empty()) {
    basis = read_basis(o.basis);
    weights = read_weights(default_weights_path(o.basis));
  } else {
    fs::create_directories(o.cache_dir);
    const std::string basis_path = stem + ".U", key_path = stem + ".key";
    if (fs::exists(basis_path) && fs::exists(key_path) && read_text(key_path) == key) {
      basis = read_basis(basis_path);
      weights = read_weights(default_weights_path(basis_path));
      progress << "demo: " << o.basis_kind << " basis from the cache (" << basis_path << ")\n";
    } else {
      if (o.basis_kind != "modal" && o.basis_kind != "polynomial") {
        throw std::invalid_argument("demo: unknown basis kind '" + o.basis_kind + "' (modal, polynomial)");
      }
      progress << "demo: " << o.basis_kind << " basis (first run; cached in " << o.cache_dir << ")\n";
      const auto start = std::chrono::steady_clock::now();
      ElasticBasisOptions options;
      options.modes = o.modes;
      options.material = o.material;
      ElasticBasis made = o.basis_kind == "modal" ? modal_basis(mesh, options, &progress)
                                                  : stiffness_scaled_polynomial_basis(mesh, options, &progress);
      basis = std::move(made.basis);
      weights = std::move(made.weights);
      write_vega_basis(basis_path, basis);
      write_weights(default_weights_path(basis_path), weights);
      std::ofstream(key_path) << key;
      assets.basis_seconds = seconds_since(start);
      progress << "demo: basis done in " << assets.basis_seconds << " s, lowest frequency " << made.frequencies_hz[0]
               << " Hz\n";
    }
  }
  assets.model = std::make_unique<SubspaceModel>(
      with_rest_contacts_excluded(SubspaceModel(std::move(mesh), basis, weights), o.exclude_rest_contacts, progress));
  assets.bvh = std::make_unique<SubspaceBvh>(*assets.model);
  // The file checks itself against the model too; models with and without the rest contacts
  // excluded keep a file each.
  const std::string certificate_path = stem + (o.exclude_rest_contacts ? "-excluding-rest-contacts" : "") + ".sscc";
  CachedCertificates cached =
      read_or_precompute_certificates(*assets.bvh, certificate_path, o.fresh_certificates, "demo", progress);
  assets.certificates = std::make_unique<Certificates>(std::move(cached.certificates));
  assets.certificate_seconds = cached.seconds;
  return assets;
}

}  // namespace sscc::validation
