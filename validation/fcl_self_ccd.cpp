#include "fcl_self_ccd.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#if SSCC_WITH_FCL
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/AABB.h>
#include <fcl/math/bv/utility.h>
#include <fcl/narrowphase/detail/traversal/collision/mesh_continuous_collision_traversal_node.h>
#include <fcl/narrowphase/detail/traversal/collision_node.h>
#endif

namespace sscc::validation {

#if SSCC_WITH_FCL

namespace {

using Model = fcl::BVHModel<fcl::AABB<double>>;

/// FCL's continuous leaf test, skipping triangle pairs that share a vertex or are excluded.
class NonAdjacentNode : public fcl::detail::MeshContinuousCollisionTraversalNode<fcl::AABB<double>> {
 public:
  explicit NonAdjacentNode(const ExcludedPairs& excluded) : excluded_(excluded) {}
  void leafTesting(int b1, int b2) const override {
    const int t1 = this->model1->getBV(b1).primitiveId();
    const int t2 = this->model2->getBV(b2).primitiveId();
    const fcl::Triangle& a = tri_indices1[t1];
    const fcl::Triangle& b = tri_indices2[t2];
    for (int i = 0; i < 3; ++i) {
      if (a[i] == b[0] || a[i] == b[1] || a[i] == b[2]) return;
    }
    if (excluded_.contains(t1, t2)) return;
    MeshContinuousCollisionTraversalNode::leafTesting(b1, b2);
  }

 private:
  const ExcludedPairs& excluded_;
};

}  // namespace

struct FclSelfCcd::Impl {
  Model model;
  ExcludedPairs excluded;
};

FclSelfCcd::FclSelfCcd(const TriangleMesh& mesh, ExcludedPairs excluded) : impl_(std::make_unique<Impl>()) {
  impl_->excluded = std::move(excluded);
  std::vector<fcl::Vector3<double>> points(mesh.vertices().begin(), mesh.vertices().end());
  std::vector<fcl::Triangle> triangles;
  for (const Triangle& t : mesh.triangles()) triangles.emplace_back(t[0], t[1], t[2]);
  impl_->model.beginModel();
  impl_->model.addSubModel(points, triangles);
  impl_->model.endModel();
}

FclSelfCcd::~FclSelfCcd() = default;

std::vector<std::pair<int, int>> FclSelfCcd::step(const std::vector<Eigen::Vector3d>& x0,
                                                  const std::vector<Eigen::Vector3d>& x1) {
  Model& m = impl_->model;
  // Previous vertices become x0 and current x1; the boxes are refitted over both.
  for (const auto* x : {&x0, &x1}) {
    m.beginUpdateModel();
    m.updateSubModel(std::vector<fcl::Vector3<double>>(x->begin(), x->end()));
    m.endUpdateModel(true, true);
  }
  NonAdjacentNode node(impl_->excluded);
  fcl::CollisionRequest<double> request(1000000);
  fcl::detail::initialize(node, m, fcl::Transform3<double>::Identity(), m, fcl::Transform3<double>::Identity(),
                          request);
  fcl::detail::selfCollide(&node, nullptr);
  std::vector<std::pair<int, int>> pairs;
  for (const auto& p : node.pairs) pairs.emplace_back(std::min(p.id1, p.id2), std::max(p.id1, p.id2));
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

#else

struct FclSelfCcd::Impl {};
FclSelfCcd::FclSelfCcd(const TriangleMesh&, ExcludedPairs) {
  throw std::logic_error("sscc was built without FCL (SSCC_WITH_FCL=OFF)");
}
FclSelfCcd::~FclSelfCcd() = default;
std::vector<std::pair<int, int>> FclSelfCcd::step(const std::vector<Eigen::Vector3d>&,
                                                  const std::vector<Eigen::Vector3d>&) {
  return {};
}

#endif

}  // namespace sscc::validation
