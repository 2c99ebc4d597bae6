#include "adsd/planner/arm_validity_checker_base.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "adsd/error.h"
#include "adsd/tolerances.h"
#include "adsd/planner/arm_kinematics.h"
#include "adsd/planner/rigid_body_scene.h"

namespace adsd::planner {

namespace {

/// Working memory of the calling thread, shared by every arm checker it runs (a thread runs one
/// query at a time; nothing in it outlives a query). Sized on first use, then reused: a query
/// allocates nothing once the vectors have grown.
struct ArmScratch {
  std::vector<double> q;
  std::vector<Pose> linkPoses;
};
ArmScratch& threadScratch() {
  thread_local ArmScratch scratch;
  return scratch;
}

/// Obstacle parts per leaf of the broad phase's box tree: a leaf's parts are tested one by one,
/// about as cheap as testing two more nodes.
constexpr std::uint32_t kObstacleLeafParts = 4;

/// Obstacle parts from which the clearance queries measure a first pair before their broad phase
/// (firstPair): with fewer, visiting every part costs less than the pair they may measure twice.
constexpr std::size_t kPartsForAFirstPair = 64;

/// Gap between two boxes given by centre and half extents (0 when they overlap), squared.
double boxGap2(const Vec3& c1, const Vec3& h1, const Vec3& c2, const Vec3& h2) {
  const Vec3 gap = ((c1 - c2).cwiseAbs() - h1 - h2).cwiseMax(0.0);
  return gap.squaredNorm();
}

}  // namespace

ArmValidityCheckerBase::ArmValidityCheckerBase(const ompl::base::SpaceInformationPtr& si,
                                               std::shared_ptr<const ArmScene> scene, double safetyMargin)
    : ompl::base::StateValidityChecker(si), scene_(std::move(scene)), safetyMargin_(safetyMargin) {
  if (!scene_ || !scene_->model) throw InputError("arm checker: no scene or no robot model");
  space_ = dynamic_cast<const ArmStateSpace*>(si->getStateSpace().get());
  if (!space_ || space_->dof() != scene_->model->dof()) {
    throw InputError("arm checker: the space must be the ArmStateSpace of " + scene_->model->sourceFile);
  }
  if (!std::isfinite(safetyMargin_) || safetyMargin_ < 0.0) {
    throw InputError("arm checker: the safety margin must be finite and >= 0, got " + std::to_string(safetyMargin_));
  }
  const ArmModel& model = *scene_->model;
  std::vector<std::size_t> bodyOfLink(model.links.size(), SIZE_MAX);
  // Reach: how far any point of a link can be from the root, for every configuration (a link's
  // frame is at most |origin| from its parent's, plus the stroke of a prismatic joint).
  std::vector<double> frameReach(model.links.size(), 0.0);
  double reach = 0.0;
  for (std::size_t l = 0; l < model.links.size(); ++l) {
    const int j = model.links[l].parentJoint;
    if (j >= 0) {
      const ArmJoint& joint = model.joints[static_cast<std::size_t>(j)];
      frameReach[l] = frameReach[joint.parentLink] + joint.origin.translation().norm() +
                      (joint.type == ArmJointType::prismatic ? std::max(std::abs(joint.lower), std::abs(joint.upper)) : 0.0);
    }
    if (!model.links[l].collision) continue;
    const Mesh& mesh = *model.links[l].collision;
    bodyOfLink[l] = linkOfBody_.size();
    linkOfBody_.push_back(l);
    const Vec3 centre = mesh.bounds().center();
    double radius = 0.0, farthest = 0.0;
    for (const TriangleIndices& t : mesh.triangles()) {
      for (std::uint32_t v : t) {
        radius = std::max(radius, (mesh.vertices()[v] - centre).norm());
        farthest = std::max(farthest, mesh.vertices()[v].norm());
      }
    }
    reach = std::max(reach, frameReach[l] + farthest);
    ballCentres_.push_back(centre);
    ballRadii_.push_back(radius);
    linkBoxes_.push_back(mesh.bounds());
    linkComponentPoints_.push_back(vertexPerComponent(mesh));
    if (!model.links[l].solids.empty()) solidBodies_.push_back(linkOfBody_.size() - 1);
  }
  selfPairIndex_.assign(linkOfBody_.size() * linkOfBody_.size(), SIZE_MAX);
  for (const auto& [a, b] : scene_->selfPairs.enabledPairs()) {
    const std::size_t ba = bodyOfLink[a], bb = bodyOfLink[b];
    selfPairIndex_[ba * linkOfBody_.size() + bb] = selfPairIndex_[bb * linkOfBody_.size() + ba] = selfPairs_.size();
    selfPairs_.emplace_back(ba, bb);
  }
  Eigen::AlignedBox3d box(Vec3::Constant(-reach), Vec3::Constant(reach));
  for (const Mesh& part : scene_->environment) {
    obstacleCentres_.push_back(part.bounds().center());
    obstacleHalves_.push_back(0.5 * part.bounds().sizes());
    if (!solidBodies_.empty()) obstacleComponentPoints_.push_back(vertexPerComponent(part));
    box.extend(part.bounds());
  }
  scale_ = box.diagonal().norm();
  obstacleOrder_.resize(obstacleCentres_.size());
  for (std::uint32_t e = 0; e < obstacleOrder_.size(); ++e) obstacleOrder_[e] = e;
  if (!obstacleOrder_.empty()) {
    buildBoxTree(obstacleCentres_, obstacleHalves_, obstacleOrder_, obstacleTree_, 0,
                 static_cast<std::uint32_t>(obstacleOrder_.size()));
  }
  std::vector<Vec3> solidCentres, solidHalves;
  for (const ConvexSolid& solid : scene_->solids) {
    solidCentres.push_back(solid.box.center());
    solidHalves.push_back(0.5 * solid.box.sizes());
    solidOrder_.push_back(static_cast<std::uint32_t>(solidOrder_.size()));
  }
  if (!solidOrder_.empty()) {
    buildBoxTree(solidCentres, solidHalves, solidOrder_, solidTree_, 0, static_cast<std::uint32_t>(solidOrder_.size()));
  }
}

std::int32_t ArmValidityCheckerBase::buildBoxTree(const std::vector<Vec3>& centres, const std::vector<Vec3>& halves,
                                                  std::vector<std::uint32_t>& order, std::vector<ObstacleNode>& tree,
                                                  std::uint32_t first, std::uint32_t count) {
  Eigen::AlignedBox3d box, spread;
  for (std::uint32_t k = first; k < first + count; ++k) {
    const std::uint32_t e = order[k];
    box.extend(centres[e] - halves[e]);
    box.extend(centres[e] + halves[e]);
    spread.extend(centres[e]);
  }
  const auto node = static_cast<std::int32_t>(tree.size());
  tree.push_back({box.center(), 0.5 * box.sizes(), first, count, -1, -1});
  if (count <= kObstacleLeafParts) return node;
  // Split at the median centre along the axis where the centres spread most.
  Vec3::Index axis = 0;
  spread.sizes().maxCoeff(&axis);
  const std::uint32_t half = count / 2;
  std::nth_element(order.begin() + first, order.begin() + first + half, order.begin() + first + count,
                   [&](std::uint32_t x, std::uint32_t y) { return centres[x][axis] < centres[y][axis]; });
  const std::int32_t left = buildBoxTree(centres, halves, order, tree, first, half);
  const std::int32_t right = buildBoxTree(centres, halves, order, tree, first + half, count - half);
  tree[static_cast<std::size_t>(node)].left = left;
  tree[static_cast<std::size_t>(node)].right = right;
  return node;
}

const Mesh& ArmValidityCheckerBase::bodyMesh(std::size_t b) const {
  return b < linkOfBody_.size() ? *scene_->model->links[linkOfBody_[b]].collision
                                : scene_->environment[b - linkOfBody_.size()];
}

std::vector<std::string> ArmValidityCheckerBase::pairsInContact(const ompl::base::State* state,
                                                                std::size_t count) const {
  const std::vector<Pose>* poses = posesFor(state);
  if (poses == nullptr) return {"a joint value that is not a number"};
  const std::vector<Pose>& linkPoses = *poses;
  const ArmModel& model = *scene_->model;
  auto linkName = [&](std::size_t body) { return "'" + model.links[linkOfBody_[body]].name + "'"; };
  // An obstacle part is named after its object.
  auto obstacleName = [&](std::size_t body) { return "'" + nameBeforeSplit(bodyMesh(body).name()) + "'"; };
  // Every pair in contact, each once: an object split into parts may touch a link with several.
  std::vector<std::string> found;
  auto note = [&](std::string what) {
    if (std::find(found.begin(), found.end(), what) == found.end()) found.push_back(std::move(what));
  };
  const Pose identity = Pose::Identity();
  for (std::size_t b = 0; b < linkOfBody_.size(); ++b) {
    const Pose& pose = linkPoses[linkOfBody_[b]];
    std::vector<std::string> touched;  // the objects whose surfaces this link meets
    for (std::size_t e = 0; e < scene_->environment.size(); ++e) {
      const std::size_t body = linkOfBody_.size() + e;
      if (!pairSeparatedAbove(b, pose, body, identity, safetyMargin_)) {
        touched.push_back(obstacleName(body));
        note("link " + linkName(b) + " and obstacle " + touched.back());
      }
    }
    // Inside a solid whose surface it does not meet: wholly inside. (A link that crosses a solid
    // has points inside too; it was said to be inside as well as touching: an outside review.)
    for (const ConvexSolid& solid : scene_->solids) {
      const std::string name = "'" + nameBeforeSplit(solid.name) + "'";  // as obstacleName() says it
      if (std::find(touched.begin(), touched.end(), name) != touched.end()) continue;
      for (const Vec3& local : linkComponentPoints_[b]) {
        if (solid.containsStrictly(pose * local, insideSlack())) note("link " + linkName(b) + " inside obstacle " + name);
      }
    }
  }
  for (const auto& [a, b] : selfPairs_) {
    if (!pairSeparatedAbove(a, linkPoses[linkOfBody_[a]], b, linkPoses[linkOfBody_[b]], safetyMargin_)) {
      note("links " + linkName(a) + " and " + linkName(b));
    }
  }
  // Inside a link's own solid, where their surfaces do not meet (as for the scene's solids).
  const std::size_t bodies = linkOfBody_.size();
  heldByALinkSolid(linkPoses, [&](std::size_t holder, std::size_t held) {
    const auto noted = [&](const std::string& what) {
      return std::find(found.begin(), found.end(), what) != found.end();
    };
    if (held >= bodies) {
      if (!noted("link " + linkName(holder) + " and obstacle " + obstacleName(held))) {
        note("obstacle " + obstacleName(held) + " inside link " + linkName(holder));
      }
    } else if (!noted("links " + linkName(holder) + " and " + linkName(held)) &&
               !noted("links " + linkName(held) + " and " + linkName(holder))) {
      note("link " + linkName(held) + " inside link " + linkName(holder));
    }
    return false;  // every one named
  });
  if (found.size() > count) {
    const std::size_t more = found.size() - count;
    found.resize(count);
    found.push_back("and " + std::to_string(more) + (more == 1 ? " more pair" : " more pairs"));
  }
  return found;
}

const ConvexSolid* ArmValidityCheckerBase::solidHolding(std::size_t body, const Pose& pose) const {
  const double slack = insideSlack();
  for (const Vec3& local : linkComponentPoints_[body]) {
    const Vec3 point = pose * local;
    // Down the solids' box tree through the boxes that hold the point.
    std::int32_t stack[64];  // median splits: depth <= log2(solids) + 1
    int top = 0;
    if (!solidTree_.empty()) stack[top++] = 0;
    while (top > 0) {
      const ObstacleNode& node = solidTree_[static_cast<std::size_t>(stack[--top])];
      if (((point - node.centre).cwiseAbs() - node.half).maxCoeff() > 0.0) continue;
      if (node.left < 0) {
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
          const ConvexSolid& solid = scene_->solids[solidOrder_[k]];
          if (solid.containsStrictly(point, slack)) return &solid;
        }
      } else {
        stack[top++] = node.left;
        stack[top++] = node.right;
      }
    }
  }
  return nullptr;
}

bool ArmValidityCheckerBase::anyLinkInsideSolid(const std::vector<Pose>& linkPoses) const {
  if (scene_->solids.empty()) return false;
  for (std::size_t b = 0; b < linkOfBody_.size(); ++b) {
    if (solidHolding(b, linkPoses[linkOfBody_[b]]) != nullptr) return true;
  }
  return false;
}

template <class Visit>
bool ArmValidityCheckerBase::forObstaclePartsNear(const Vec3& centre, const Vec3& half, double reach2,
                                                  Visit visit) const {
  std::int32_t stack[64];  // median splits: depth <= log2(parts) + 1
  int top = 0;
  if (!obstacleTree_.empty()) stack[top++] = 0;
  while (top > 0) {
    const ObstacleNode& node = obstacleTree_[static_cast<std::size_t>(stack[--top])];
    if (boxGap2(centre, half, node.centre, node.half) > reach2) continue;
    if (node.left >= 0) {
      stack[top++] = node.left;
      stack[top++] = node.right;
      continue;
    }
    // At a leaf, each part's own box (cheap) before the caller's test.
    for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
      const std::size_t e = obstacleOrder_[k];
      const double box2 = boxGap2(centre, half, obstacleCentres_[e], obstacleHalves_[e]);
      if (box2 <= reach2 && visit(e, box2)) return true;
    }
  }
  return false;
}

template <class Counts>
bool ArmValidityCheckerBase::heldByALinkSolid(const std::vector<Pose>& linkPoses, Counts counts) const {
  const double slack = insideSlack();
  const std::size_t n = linkOfBody_.size();
  for (const std::size_t b : solidBodies_) {
    const Pose& pose = linkPoses[linkOfBody_[b]];
    const Pose toLink = pose.inverse();
    const std::vector<ConvexSolid>& solids = scene_->model->links[linkOfBody_[b]].solids;
    // Whether point p (link frame) lies in one of the link's solids.
    const auto inASolid = [&](const Vec3& p) {
      return std::any_of(solids.begin(), solids.end(),
                         [&](const ConvexSolid& solid) { return solid.containsStrictly(p, slack); });
    };
    // Obstacle parts whose boxes meet a solid's (world frame).
    for (const ConvexSolid& solid : solids) {
      const Vec3 centre = pose * solid.box.center();
      const Vec3 half = pose.linear().cwiseAbs() * (0.5 * solid.box.sizes());
      const bool found = forObstaclePartsNear(centre, half, 0.0, [&](std::size_t e, double) {
        for (const Vec3& p : obstacleComponentPoints_[e]) {
          if (solid.containsStrictly(toLink * p, slack) && counts(b, n + e)) return true;
        }
        return false;
      });
      if (found) return true;
    }
    // The other link of each enabled pair, its points moved into this link's frame once.
    for (const auto& [x, y] : selfPairs_) {
      if (x != b && y != b) continue;
      const std::size_t other = x == b ? y : x;
      const Pose toHolder = toLink * linkPoses[linkOfBody_[other]];
      for (const Vec3& p : linkComponentPoints_[other]) {
        if (inASolid(toHolder * p) && counts(b, other)) return true;
      }
    }
  }
  return false;
}

const std::vector<Pose>* ArmValidityCheckerBase::posesFor(const ompl::base::State* state) const {
  ArmScratch& s = threadScratch();
  s.q.resize(space_->dof());
  space_->toJoints(state, s.q.data());
  if (!std::all_of(s.q.begin(), s.q.end(), [](double x) { return std::isfinite(x); })) return nullptr;
  forwardKinematics(*scene_->model, s.q.data(), s.linkPoses);
  return &s.linkPoses;
}

double ArmValidityCheckerBase::broadPhase(const std::vector<Pose>& linkPoses, double limit,
                                          std::vector<PairBound>& pairs) const {
  pairs.clear();
  // Roundoff allowance of the bounds below (the core's own, adsd/tolerances.h), at the scene's scale.
  const double slack = tolerance::kBoundSafetyUlps * tolerance::kEpsilon * scale_;
  const double reach = limit + slack;
  const double reach2 = reach * reach;
  const std::size_t n = linkOfBody_.size();
  // Posed balls and world boxes of the links, on the stack for the usual arm (a few links).
  constexpr std::size_t kStackLinks = 32;
  Vec3 ballStack[kStackLinks], boxCentreStack[kStackLinks], boxHalfStack[kStackLinks];
  std::vector<Vec3> ballHeap, centreHeap, halfHeap;
  Vec3* ball = ballStack;
  Vec3* boxCentre = boxCentreStack;
  Vec3* boxHalf = boxHalfStack;
  if (n > kStackLinks) {
    ballHeap.resize(n), centreHeap.resize(n), halfHeap.resize(n);
    ball = ballHeap.data(), boxCentre = centreHeap.data(), boxHalf = halfHeap.data();
  }
  for (std::size_t b = 0; b < n; ++b) {
    ball[b] = linkPoses[linkOfBody_[b]] * ballCentres_[b];
    posedLinkBox(linkPoses, b, boxCentre[b], boxHalf[b]);
  }
  // Link × obstacle: down the parts' box tree while the link's box can reach a node's; at a leaf,
  // the box gap first (cheap), the ball gap only for the pairs it keeps.
  for (std::size_t b = 0; b < n; ++b) {
    const double ballReach = reach + ballRadii_[b];
    forObstaclePartsNear(boxCentre[b], boxHalf[b], reach2, [&](std::size_t e, double box2) {
      const double ball2 = boxGap2(ball[b], Vec3::Zero(), obstacleCentres_[e], obstacleHalves_[e]);
      if (ball2 <= ballReach * ballReach) {
        pairs.push_back({std::max({0.0, std::sqrt(ball2) - ballRadii_[b], std::sqrt(box2)}), b, n + e});
      }
      return false;
    });
  }
  // Link × link, the enabled pairs: ball–ball and box–box gaps.
  for (const auto& [a, b] : selfPairs_) {
    const double balls = (ball[a] - ball[b]).norm() - ballRadii_[a] - ballRadii_[b];
    if (balls > reach) continue;
    const double box2 = boxGap2(boxCentre[a], boxHalf[a], boxCentre[b], boxHalf[b]);
    if (box2 > reach2) continue;
    pairs.push_back({std::max({0.0, balls, std::sqrt(box2)}), a, b});
  }
  return slack;
}

void ArmValidityCheckerBase::posedLinkBox(const std::vector<Pose>& linkPoses, std::size_t body, Vec3& centre,
                                          Vec3& half) const {
  const Pose& pose = linkPoses[linkOfBody_[body]];
  centre = pose * linkBoxes_[body].center();
  half = pose.linear().cwiseAbs() * (0.5 * linkBoxes_[body].sizes());
}

bool ArmValidityCheckerBase::firstPair(const std::vector<Pose>& linkPoses, std::size_t& body,
                                       std::size_t& part) const {
  if (obstacleTree_.empty()) return false;
  // Each link down the tree into the child whose box is nearer its own, to a leaf, and there the
  // part whose box is nearest; of all links, the pair of the nearest boxes.
  double nearestGap2 = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < linkOfBody_.size(); ++b) {
    Vec3 centre, half;
    posedLinkBox(linkPoses, b, centre, half);
    const ObstacleNode* node = &obstacleTree_[0];
    while (node->left >= 0) {
      const ObstacleNode& left = obstacleTree_[static_cast<std::size_t>(node->left)];
      const ObstacleNode& right = obstacleTree_[static_cast<std::size_t>(node->right)];
      node = boxGap2(centre, half, left.centre, left.half) <= boxGap2(centre, half, right.centre, right.half) ? &left
                                                                                                          : &right;
    }
    for (std::uint32_t k = node->first; k < node->first + node->count; ++k) {
      const std::size_t e = obstacleOrder_[k];
      const double gap2 = boxGap2(centre, half, obstacleCentres_[e], obstacleHalves_[e]);
      if (gap2 < nearestGap2) nearestGap2 = gap2, body = b, part = e;
    }
  }
  return std::isfinite(nearestGap2);
}

bool ArmValidityCheckerBase::separatedAbove(const std::vector<Pose>& linkPoses, double margin) const {
  thread_local std::vector<PairBound> pairs;
  broadPhase(linkPoses, margin, pairs);
  // Nearest first: a collision is most likely with the nearest part.
  if (pairs.size() > 1) {
    std::sort(pairs.begin(), pairs.end(), [](const PairBound& x, const PairBound& y) { return x.lower < y.lower; });
  }
  const std::size_t n = linkOfBody_.size();
  for (const PairBound& p : pairs) {
    const Pose& poseA = linkPoses[linkOfBody_[p.a]];
    const Pose poseB = p.b < n ? linkPoses[linkOfBody_[p.b]] : Pose::Identity();
    if (!pairSeparatedAbove(p.a, poseA, p.b, poseB, margin)) return false;
  }
  return true;
}

double ArmValidityCheckerBase::distanceUpTo(const std::vector<Pose>& linkPoses, double cap,
                                            bool obstaclesOnly) const {
  if (!(cap > 0.0)) return 0.0;  // nothing asked for; 0 is a lower bound of every distance
  if (anyLinkInsideSolid(linkPoses)) return 0.0;
  const std::size_t bodies = linkOfBody_.size();
  if (heldByALinkSolid(linkPoses, [&](std::size_t, std::size_t held) { return !obstaclesOnly || held >= bodies; })) {
    return 0.0;
  }
  // With many obstacle parts, one link-part pair measured first bounds the distance, so that the
  // broad phase visits only the parts within it, not every part against every link: visiting it
  // first is what the loop below would do with it, and the answer is the same. The KR5 among
  // 20 000 small boxes (adsd plan --objective clearance --planner rrtstar): 13.5 ms per clearance
  // query before, linear in the boxes, 0.64 ms with this; among 1 000, 0.35 ms before, 0.08 after.
  const std::size_t n = linkOfBody_.size();
  double first = cap;
  std::size_t body = 0, part = 0;
  bool measuredFirst = false;
  if (obstacleCentres_.size() >= kPartsForAFirstPair && firstPair(linkPoses, body, part)) {
    const PairDistance d = pairDistance(body, linkPoses[linkOfBody_[body]], n + part, Pose::Identity(), cap);
    measuredFirst = true;
    if (!d.reachedCap) first = std::min(cap, d.lower);
    if (first <= 0.0) return first;  // in contact
  }
  thread_local std::vector<PairBound> pairs;
  const double slack = broadPhase(linkPoses, first, pairs);
  if (obstaclesOnly) {
    pairs.erase(std::remove_if(pairs.begin(), pairs.end(), [n](const PairBound& p) { return p.b < n; }), pairs.end());
  }
  const auto fartherFirst = [](const PairBound& x, const PairBound& y) { return x.lower > y.lower; };
  std::make_heap(pairs.begin(), pairs.end(), fartherFirst);
  double best = first;  // a lower bound on the distance, valid for every pair visited or skipped
  while (!pairs.empty()) {
    std::pop_heap(pairs.begin(), pairs.end(), fartherFirst);
    const PairBound p = pairs.back();
    pairs.pop_back();
    if (p.lower > best + slack) break;  // this pair and all left are no nearer than `best`
    if (measuredFirst && p.a == body && p.b == n + part) continue;  // measured before the broad phase
    const Pose& poseA = linkPoses[linkOfBody_[p.a]];
    const Pose poseB = p.b < n ? linkPoses[linkOfBody_[p.b]] : Pose::Identity();
    const PairDistance d = pairDistance(p.a, poseA, p.b, poseB, best);
    if (!d.reachedCap) best = std::min(best, d.lower);
    if (best <= 0.0) break;  // in contact: nothing is nearer
  }
  return best;
}

double ArmValidityCheckerBase::weightedClearanceUpTo(const ompl::base::State* state, const double* linkWeights,
                                                     const double* selfPairWeights, double subtract,
                                                     double cap) const {
  ScopedQueryTimer timer(counters_, ScopedQueryTimer::Kind::clearance);
  const std::vector<Pose>* poses = posesFor(state);
  if (poses == nullptr) return 0.0;
  const std::vector<Pose>& linkPoses = *poses;
  // A link inside a solid is at distance 0 from it, weighted as the link's pairs with obstacles.
  double inside = cap;
  for (std::size_t b = 0; b < linkOfBody_.size() && !scene_->solids.empty(); ++b) {
    const double w = linkWeights[linkOfBody_[b]];
    if (w > 0.0 && solidHolding(b, linkPoses[linkOfBody_[b]]) != nullptr) inside = std::min(inside, -subtract / w);
  }
  // And an obstacle or a link inside a link's own solid, weighted as that pair.
  const std::size_t bodies = linkOfBody_.size();
  heldByALinkSolid(linkPoses, [&](std::size_t holder, std::size_t held) {
    const double w =
        held < bodies ? selfPairWeights[selfPairIndex_[holder * bodies + held]] : linkWeights[linkOfBody_[holder]];
    if (w > 0.0) inside = std::min(inside, -subtract / w);
    return w > 0.0;
  });
  // At most 0: the caller rejects, as the pairs' loop below stops at 0 without their minimum.
  if (inside < cap) return inside;
  const std::size_t n = linkOfBody_.size();
  const auto weightOf = [&](const PairBound& p) {
    return p.b < n ? selfPairWeights[selfPairIndex_[p.a * n + p.b]] : linkWeights[linkOfBody_[p.a]];
  };
  double best = cap;
  // Each pair has its own weight, so the broad phase culls by distance only below what no pair,
  // at the largest weight, can beat best by: with many obstacle parts, one link-part pair measured
  // first sets it (as distanceUpTo does; visiting it first is what the loop below would do).
  double limit = std::numeric_limits<double>::infinity();
  std::size_t body = 0, part = 0;
  bool measuredFirst = false;
  if (obstacleCentres_.size() >= kPartsForAFirstPair && firstPair(linkPoses, body, part)) {
    const double w = linkWeights[linkOfBody_[body]];
    const double needed = cap * w + subtract;
    if (w > 0.0 && needed > 0.0) {
      const PairDistance d = pairDistance(body, linkPoses[linkOfBody_[body]], n + part, Pose::Identity(), needed);
      measuredFirst = true;
      if (!d.reachedCap) best = std::min(best, (d.lower - subtract) / w);
      if (best <= 0.0) return best;  // within the margin: the caller rejects
      double heaviest = 0.0;
      for (std::size_t b = 0; b < n; ++b) heaviest = std::max(heaviest, linkWeights[linkOfBody_[b]]);
      for (std::size_t k = 0; k < selfPairs_.size(); ++k) heaviest = std::max(heaviest, selfPairWeights[k]);
      // A pair whose distance bound passes this has a key of at least best (weights <= heaviest).
      limit = std::max(0.0, best * heaviest + subtract);
    }
  }
  thread_local std::vector<PairBound> pairs;
  const double slack = broadPhase(linkPoses, limit, pairs);
  // The key of a pair: a lower bound of its weighted clearance (its distance bound less the
  // roundoff allowance); weightless pairs leave, the rest are visited smallest key first.
  std::size_t kept = 0;
  for (const PairBound& p : pairs) {
    const double w = weightOf(p);
    if (w > 0.0) pairs[kept++] = {(p.lower - slack - subtract) / w, p.a, p.b};
  }
  pairs.resize(kept);
  const auto fartherFirst = [](const PairBound& x, const PairBound& y) { return x.lower > y.lower; };
  std::make_heap(pairs.begin(), pairs.end(), fartherFirst);
  while (!pairs.empty()) {
    std::pop_heap(pairs.begin(), pairs.end(), fartherFirst);
    const PairBound p = pairs.back();
    pairs.pop_back();
    if (p.lower >= best) break;  // this pair and all left are no nearer, weighted
    if (measuredFirst && p.a == body && p.b == n + part) continue;  // measured before the broad phase
    const double w = weightOf(p);
    const Pose& poseA = linkPoses[linkOfBody_[p.a]];
    const Pose poseB = p.b < n ? linkPoses[linkOfBody_[p.b]] : Pose::Identity();
    // The pair's distance matters only below best * w + subtract.
    const double needed = best * w + subtract;
    if (!(needed > 0.0)) break;  // only when cap <= 0: nothing is asked for
    const PairDistance d = pairDistance(p.a, poseA, p.b, poseB, needed);
    if (!d.reachedCap) best = std::min(best, (d.lower - subtract) / w);
    if (best <= 0.0) break;  // within the margin: the caller rejects
  }
  return best;
}

bool ArmValidityCheckerBase::isValid(const ompl::base::State* state) const {
  ScopedQueryTimer timer(counters_, ScopedQueryTimer::Kind::validity);
  if (!si_->satisfiesBounds(state)) return false;
  const std::vector<Pose>* poses = posesFor(state);
  return poses != nullptr && validAt(*poses);
}

bool ArmValidityCheckerBase::validAt(const std::vector<Pose>& linkPoses) const {
  // The solids last: most states in collision fail a pair first, and the test is for free ones.
  return separatedAbove(linkPoses, safetyMargin_) && !anyLinkInsideSolid(linkPoses) &&
         !heldByALinkSolid(linkPoses, [](std::size_t, std::size_t) { return true; });
}

bool ArmValidityCheckerBase::isValid(const ompl::base::State* state, double& dist) const {
  ScopedQueryTimer timer(counters_, ScopedQueryTimer::Kind::clearance);
  const std::vector<Pose>* poses = posesFor(state);
  dist = poses != nullptr ? distanceUpTo(*poses, std::numeric_limits<double>::infinity()) : 0.0;
  if (!si_->satisfiesBounds(state) || poses == nullptr) return false;
  if (dist > safetyMargin_) return true;
  // A lower bound (a tolerance's, a cap's) at or below the margin does not decide, as the rigid
  // checker's isValid(state, dist) says (rigid_body_validity_checker.cpp): isValid(state) does.
  return specs_.clearanceComputationType != ompl::base::StateValidityCheckerSpecs::EXACT && validAt(*poses);
}

double ArmValidityCheckerBase::clearance(const ompl::base::State* state) const {
  ScopedQueryTimer timer(counters_, ScopedQueryTimer::Kind::clearance);
  const std::vector<Pose>* poses = posesFor(state);
  return poses != nullptr ? distanceUpTo(*poses, std::numeric_limits<double>::infinity()) : 0.0;
}

double ArmValidityCheckerBase::clearanceUpTo(const ompl::base::State* state, double cap) const {
  ScopedQueryTimer timer(counters_, ScopedQueryTimer::Kind::clearance);
  const std::vector<Pose>* poses = posesFor(state);
  return poses != nullptr ? distanceUpTo(*poses, cap) : 0.0;
}

double ArmValidityCheckerBase::obstacleClearanceUpTo(const ompl::base::State* state, double cap) const {
  ScopedQueryTimer timer(counters_, ScopedQueryTimer::Kind::clearance);
  const std::vector<Pose>* poses = posesFor(state);
  return poses != nullptr ? distanceUpTo(*poses, cap, true) : 0.0;
}

}  // namespace adsd::planner
