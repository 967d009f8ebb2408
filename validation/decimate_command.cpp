#include "decimate_command.hpp"

// OpenMesh's headers trip a false maybe-uninitialized warning in its property containers.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#pragma GCC diagnostic pop

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "sscc/mesh/mesh_io.hpp"

namespace sscc::validation {

namespace {

constexpr double kMaxNormalDeviationDegrees = 45.0;

}  // namespace

long run_decimate(const DecimateCommandOptions& o, std::ostream& out, std::ostream& progress) {
  using Mesh = OpenMesh::TriMesh_ArrayKernelT<>;
  if (o.triangles < 4) throw std::invalid_argument("decimate: --triangles must be at least 4");
  // Read with the project's reader (its checks and messages), then hand over to OpenMesh.
  const TriangleMesh input = read_mesh(o.mesh);
  const auto start = std::chrono::steady_clock::now();
  Mesh mesh;
  std::vector<Mesh::VertexHandle> handles;
  for (const Eigen::Vector3d& p : input.vertices()) handles.push_back(mesh.add_vertex(Mesh::Point(p[0], p[1], p[2])));
  int refused = 0;
  for (const Triangle& t : input.triangles()) {
    if (!mesh.add_face(handles[t[0]], handles[t[1]], handles[t[2]]).is_valid()) ++refused;
  }
  if (refused > 0) progress << "decimate: " << refused << " non-manifold triangles left out\n";
  OpenMesh::Decimater::DecimaterT<Mesh> decimater(mesh);
  OpenMesh::Decimater::ModQuadricT<Mesh>::Handle quadric;
  decimater.add(quadric);
  // No collapse may turn a face's normal by more than this: fold-overs are what make a
  // decimated surface intersect itself.
  OpenMesh::Decimater::ModNormalFlippingT<Mesh>::Handle flipping;
  decimater.add(flipping);
  decimater.module(flipping).set_max_normal_deviation(kMaxNormalDeviationDegrees);
  if (!decimater.initialize()) throw std::runtime_error("decimate: OpenMesh's decimater did not initialise");
  decimater.decimate_to_faces(0, static_cast<std::size_t>(o.triangles));
  mesh.garbage_collection();
  if (!OpenMesh::IO::write_mesh(mesh, o.output)) throw std::runtime_error(o.output + ": cannot write the mesh");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress << "decimate: wrote " << o.output << " (" << mesh.n_vertices() << " vertices)\n";
  char line[160];
  std::snprintf(line, sizeof line, "decimate: input_triangles=%d output_triangles=%zu time_s=%.3f",
                input.triangle_count(), mesh.n_faces(), seconds);
  out << line << '\n';
  return 0;
}

}  // namespace sscc::validation
