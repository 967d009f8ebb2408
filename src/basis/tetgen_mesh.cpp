#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sscc/basis/volume_mesh.hpp"

#define TETLIBRARY
#include <tetgen.h>

namespace sscc {

namespace {

std::string tetgen_error(int code) {
  switch (code) {
    case 1: return "TetGen ran out of memory";
    case 2: return "TetGen reported an internal error";
    case 3: return "TetGen found self-intersecting surface triangles";
    case 4: return "TetGen found a very small input feature size";
    case 5: return "TetGen found two very close input facets";
    case 10: return "TetGen found an input error";
    default: return "TetGen failed with code " + std::to_string(code);
  }
}

}  // namespace

VolumeMesh tetrahedralize_surface(const TriangleMesh& mesh, double quality, double max_volume) {
  if (!(quality >= 1.0)) throw std::invalid_argument("tetrahedralize_surface: quality bound must be at least 1");
  if (!(max_volume >= 0.0) || !std::isfinite(max_volume)) {
    throw std::invalid_argument("tetrahedralize_surface: the largest tetrahedron volume must be >= 0 (0: no bound)");
  }
  tetgenio in;
  tetgenio out;
  in.firstnumber = 0;
  in.numberofpoints = mesh.vertex_count();
  in.pointlist = new REAL[3 * in.numberofpoints];
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    for (int k = 0; k < 3; ++k) in.pointlist[3 * v + k] = mesh.vertices()[v][k];
  }
  in.numberoffacets = mesh.triangle_count();
  in.facetlist = new tetgenio::facet[in.numberoffacets];
  for (int f = 0; f < mesh.triangle_count(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k) facet.polygonlist[0].vertexlist[k] = mesh.triangles()[f][k];
  }
  // p: a piecewise linear complex; q: quality bound; Y: no Steiner points on the surface,
  // so the surface vertices stay the first nodes; z: zero-based; Q: quiet.
  std::ostringstream switches_text;
  switches_text << std::setprecision(17) << "pq" << quality << "YzQ";
  if (max_volume > 0.0) switches_text << "a" << max_volume;  // a: largest tetrahedron volume
  std::string switches = switches_text.str();
  try {
    tetrahedralize(&switches[0], &in, &out);
  } catch (int code) {
    throw std::runtime_error(tetgen_error(code));
  }
  if (out.numberofpoints < mesh.vertex_count() || out.numberoftetrahedra == 0) {
    throw std::runtime_error("TetGen returned no tetrahedra");
  }
  VolumeMesh volume;
  volume.method = "tetgen";
  volume.nodes.resize(out.numberofpoints);
  for (int n = 0; n < out.numberofpoints; ++n) {
    volume.nodes[n] = Eigen::Vector3d(out.pointlist[3 * n], out.pointlist[3 * n + 1], out.pointlist[3 * n + 2]);
  }
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    if (volume.nodes[v] != mesh.vertices()[v]) {
      throw std::runtime_error("TetGen moved surface vertex " + std::to_string(v) + " (duplicate vertices?)");
    }
  }
  volume.tetrahedra.resize(out.numberoftetrahedra);
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    Tetrahedron tet;
    for (int k = 0; k < 4; ++k) tet[k] = out.tetrahedronlist[out.numberofcorners * t + k];
    volume.tetrahedra[t] = positively_oriented(volume.nodes, tet);
  }
  volume.embedding.resize(mesh.vertex_count(), out.numberofpoints);
  volume.embedding.reserve(Eigen::VectorXi::Ones(mesh.vertex_count()));
  for (int v = 0; v < mesh.vertex_count(); ++v) volume.embedding.insert(v, v) = 1.0;
  volume.embedding.makeCompressed();
  return volume;
}

}  // namespace sscc
