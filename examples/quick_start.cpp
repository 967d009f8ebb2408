// The README's C++ example, whole: a mesh, its modal basis, certificates, one certified step
// and one that collides, with the contact points and normals of what it reports.
//
//   quick_start MESH.off      (the README runs it on data/bunny1k.off)
#include <Eigen/Core>

#include <array>
#include <cmath>
#include <iostream>
#include <vector>

#include "sscc/sscc.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: quick_start MESH.off\n";
    return 2;
  }
  const char* path = argv[1];
  // README: begin
  sscc::TriangleMesh mesh = sscc::read_mesh(path);  // OFF, OBJ or PLY, in metres
  sscc::ElasticBasisOptions options;                // rubber by default (Pa, kg/m^3)
  options.modes = 12;
  sscc::ElasticBasis modal = sscc::modal_basis(mesh, options);  // TetGen (voxels for open scans)
  sscc::SubspaceModel model(mesh, modal.basis, modal.weights);  // x = p + U q, ||q||_M^2 = strain energy
  sscc::SubspaceBvh bvh(model);
  sscc::Certificates certificates = sscc::Certificates::precompute(bvh);  // once; write() and read() a file
  sscc::SelfCcd detector(bvh, certificates);                              // immutable: query from any thread
  Eigen::VectorXd q0 = Eigen::VectorXd::Zero(12), q1 = Eigen::VectorXd::Zero(12);
  q1[0] = 0.5 * certificates.node_radius(0) / std::sqrt(modal.weights[0]);  // inside the root's radius
  sscc::SelfCcdReport quiet = detector.query(q0, q1);                       // decided in O(r), no traversal
  q1[0] = 20 * certificates.node_radius(0) / std::sqrt(modal.weights[0]);   // far past it: the ears meet
  sscc::SelfCcdReport report = detector.query(q0, q1);
  Eigen::VectorXd s0 = model.scaled_coordinates(q0), s1 = model.scaled_coordinates(q1);
  std::vector<sscc::ContactFrame> frames;                  // what a response needs
  for (const sscc::FeatureContact& f : report.features) {  // vertex-face or edge-edge, with toi
    std::array<int, 4> v = sscc::contact_vertices(mesh, mesh, f.kind, f.first, f.second);
    std::array<Eigen::Vector3d, 4> x0, x1;  // the four vertices at q0 and q1
    for (int i = 0; i < 4; ++i) x0[i] = model.position(v[i], s0), x1[i] = model.position(v[i], s1);
    frames.push_back(sscc::contact_frame(f.kind, x0, x1, f.toi));  // barycentric weights, unit normal
  }
  // README: end
  std::cout << "certified step: " << (quiet.stats.root_certified ? "decided by the root certificate" : "traversed")
            << ", " << quiet.pairs.size() << " pairs\n";
  std::cout << "colliding step: " << report.pairs.size() << " triangle pairs, " << report.features.size()
            << " feature contacts (" << frames.size() << " contact frames), earliest toi " << report.earliest_toi
            << "\n";
  return quiet.stats.root_certified && report.collided() ? 0 : 1;
}
