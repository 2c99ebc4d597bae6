#include "viewer_page.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "adsd/error.h"
#include "adsd/planner/rigid_body_scene.h"
#include "output_file.h"

namespace adsd::app {

namespace viewer_assets {
// Written at build time by embed_viewer_assets.cmake from viewer/viewer.html and the npm package
// `three` (viewer/package-lock.json pins its version).
extern const char kViewerTemplate[];
extern const char kThreeCore[];
extern const char kThreeModule[];
extern const char kOrbitControls[];
}  // namespace viewer_assets

namespace {

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t v = static_cast<std::uint32_t>(bytes[i]) << 16;
    if (n > 1) v |= static_cast<std::uint32_t>(bytes[i + 1]) << 8;
    if (n > 2) v |= bytes[i + 2];
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += n > 1 ? kDigits[(v >> 6) & 63] : '=';
    out += n > 2 ? kDigits[v & 63] : '=';
  }
  return out;
}

/// Little-endian, as the page's typed arrays read them on every browser's platform.
template <class Unsigned>
void appendLittleEndian(std::vector<std::uint8_t>& bytes, Unsigned v) {
  for (std::size_t k = 0; k < sizeof v; ++k) bytes.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
}

template <class Unsigned, class Real>
void appendBits(std::vector<std::uint8_t>& bytes, Real x) {
  static_assert(sizeof(Unsigned) == sizeof(Real));
  Unsigned bits;
  std::memcpy(&bits, &x, sizeof bits);
  appendLittleEndian(bytes, bits);
}

/// The meshes of \p parts as one, for drawing: float32 positions measured from \p origin and
/// uint32 indices, base64.
std::string meshJson(const std::vector<const Mesh*>& parts, const Vec3& origin = Vec3::Zero()) {
  std::vector<std::uint8_t> positions, indices;
  std::uint32_t offset = 0;
  for (const Mesh* m : parts) {
    for (const Vec3& v : m->vertices()) {
      for (int k = 0; k < 3; ++k) appendBits<std::uint32_t>(positions, static_cast<float>(v[k] - origin[k]));
    }
    for (const TriangleIndices& t : m->triangles()) {
      for (const std::uint32_t i : t) appendLittleEndian(indices, offset + i);
    }
    offset += static_cast<std::uint32_t>(m->vertices().size());
  }
  return "{\"positions\":\"" + base64(positions) + "\",\"indices\":\"" + base64(indices) + "\"}";
}

/// A JSON string; '<' is escaped so that no text can close the page's <script> element.
std::string jsonString(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || c == '<' || c == '>' || c == '&') {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", u);
      out += buffer;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string htmlText(std::string_view s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

/// Shortest text that reads back as the same double; every value here is finite (poses of valid
/// states, distances between mesh points, joint values), and a non-finite one is our bug.
void appendNumber(std::string& out, double x) {
  if (!std::isfinite(x)) throw std::logic_error("viewer: a non-finite number in the page's data");
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  out += buffer;
}

template <class Numbers>
void appendArray(std::string& out, const Numbers& values) {
  out += '[';
  bool first = true;
  for (const double v : values) {
    if (!first) out += ',';
    first = false;
    appendNumber(out, v);
  }
  out += ']';
}

void appendArray(std::string& out, std::initializer_list<double> values) { appendArray<>(out, values); }

/// [x, y, z, qx, qy, qz, qw]: the order of three.js's position and quaternion.
std::array<double, 7> poseNumbers(const Pose& pose) {
  const Eigen::Quaterniond q(pose.rotation());
  const Vec3 t = pose.translation();
  return {t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w()};
}

/// One pose per body, as JSON arrays.
void appendPoses(std::string& out, const std::vector<Pose>& poses) {
  out += '[';
  for (std::size_t i = 0; i < poses.size(); ++i) {
    if (i > 0) out += ',';
    appendArray(out, poseNumbers(poses[i]));
  }
  out += ']';
}

/// The page's data: the JSON object viewer/viewer.html reads (its head comment lists the fields).
std::string pageJson(const ViewerPage& page) {
  const std::size_t bodies = page.bodies.size();
  if (bodies == 0 || page.states.empty() || page.environment == nullptr || page.start.size() != bodies ||
      page.goal.size() != bodies) {
    throw std::logic_error("viewer: a page needs bodies, an environment, states, and a start and goal pose per body");
  }
  std::string out = "{\"name\":" + jsonString(page.name) + ",\"space\":" + jsonString(page.space) +
                    ",\"source\":" + jsonString(page.source) + ",\"up\":";
  appendArray(out, {page.up.x(), page.up.y(), page.up.z()});
  std::vector<const Mesh*> environment;
  Eigen::AlignedBox3d bounds;
  for (const Mesh& m : *page.environment) {
    environment.push_back(&m);
    for (const Vec3& v : m.vertices()) bounds.extend(v);
  }
  // The environment's float32 positions are measured from the centre of its box, which the page
  // keeps in float64: in world coordinates, a scene 1.2e6 from the origin had its 1 cm wall drawn
  // 12.5 cm thick, and one 1e12 away collapsed to a point (an adversarial review).
  const Vec3 origin = bounds.isEmpty() ? Vec3::Zero() : Vec3(bounds.center());
  out += ",\"origin\":";
  appendArray(out, {origin.x(), origin.y(), origin.z()});
  out += ",\"environment\":" + meshJson(environment, origin) + ",\"bodies\":[";
  for (std::size_t b = 0; b < bodies; ++b) {
    out += (b > 0 ? ",{\"name\":" : "{\"name\":") + jsonString(page.bodies[b].name) +
           ",\"mesh\":" + meshJson(page.bodies[b].parts) + "}";
  }
  out += "],\"start\":";
  appendPoses(out, page.start);
  out += ",\"goal\":";
  appendPoses(out, page.goal);

  // Per state, the body poses as float64 (exact, and a third of their text's size), then the
  // clearance, the closest points and the joints as JSON.
  std::vector<std::uint8_t> poses;
  poses.reserve(page.states.size() * bodies * 7 * 8);
  std::string clearances = "[", witnesses = "[", closest = "[", joints = "[";
  for (std::size_t i = 0; i < page.states.size(); ++i) {
    const ViewerState& s = page.states[i];
    if (s.bodyPoses.size() != bodies || s.joints.size() != page.jointNames.size()) {
      throw std::logic_error("viewer: state " + std::to_string(i) + " has the wrong number of poses or joints");
    }
    for (const Pose& p : s.bodyPoses) {
      for (const double x : poseNumbers(p)) {
        if (!std::isfinite(x)) throw std::logic_error("viewer: a non-finite pose in the page's data");
        appendBits<std::uint64_t>(poses, x);
      }
    }
    const char* comma = i > 0 ? "," : "";
    clearances += comma, witnesses += comma, closest += comma, joints += comma;
    appendNumber(clearances, s.clearance);
    const ClosestPoints& c = s.closest;
    appendArray(witnesses, {c.onA.x(), c.onA.y(), c.onA.z(), c.onB.x(), c.onB.y(), c.onB.z()});
    closest += "[" + std::to_string(c.bodyA) + "," + std::to_string(c.bodyB) + "," + jsonString(c.obstacle) + "]";
    appendArray(joints, s.joints);
  }
  out += ",\"poses\":\"" + base64(poses) + "\",\"clearance\":" + clearances + "],\"witnesses\":" + witnesses +
         "],\"closest\":" + closest + "],\"jointNames\":[";
  for (std::size_t j = 0; j < page.jointNames.size(); ++j) out += (j > 0 ? "," : "") + jsonString(page.jointNames[j]);
  return out + "],\"joints\":" + joints + "]}";
}

/// The template with each marker replaced by its text. Every marker must be there exactly once;
/// markers are found in the template only, never in the texts put in (a problem named like one).
std::string fillTemplate(std::string_view page, std::vector<std::pair<std::string_view, std::string_view>> fills) {
  std::vector<std::pair<std::size_t, std::size_t>> at;  // (position in the template, fill)
  for (std::size_t f = 0; f < fills.size(); ++f) {
    const std::string_view marker = fills[f].first;
    const std::size_t p = page.find(marker);
    if (p == std::string_view::npos || page.find(marker, p + 1) != std::string_view::npos) {
      throw std::logic_error("viewer template: marker " + std::string(marker) + " is not there exactly once");
    }
    at.emplace_back(p, f);
  }
  std::sort(at.begin(), at.end());
  std::string out;
  std::size_t from = 0;
  for (const auto& [p, f] : at) {
    out.append(page.substr(from, p - from));
    out.append(fills[f].second);
    from = p + fills[f].first.size();
  }
  out.append(page.substr(from));
  return out;
}

/// The closest points of the pair of \p pairs whose distance is \p clearance (writeViewerPage()).
/// A state with a body point \p inside a solid obstacle, whose surfaces no pair within the slack
/// reaches, is shown by that point: the nearest surfaces of the second pass were another pair's,
/// 0.02 apart on a page saying clearance 0 (an adversarial review).
ClosestPoints closestPoints(const std::vector<CandidatePair>& pairs, double clearance, double slack,
                            DistanceScratch& scratch, const std::optional<ClosestPoints>& inside) {
  if (pairs.empty()) throw std::logic_error("viewer: no mesh pair to find the closest points in");
  double cap = clearance + slack;
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1 && inside) return *inside;
    bool found = false;
    ClosestPoints best;
    for (const CandidatePair& p : pairs) {
      const DistanceResult d = distance(*p.a, p.poseA, *p.b, p.poseB,
                                        std::isfinite(cap) ? DistanceOptions::cappedAt(cap) : DistanceOptions::exactDistance(),
                                        scratch);
      if (d.status == DistanceStatus::beyondCap) continue;
      if (!found || d.distance < cap) {
        cap = d.distance;
        best = {p.bodyA, p.bodyB, d.witnessA, d.witnessB,
                p.bodyB == ClosestPoints::kEnvironment ? planner::nameBeforeSplit(p.b->name()) : std::string()};
        found = true;
      }
      if (cap <= 0.0) return best;  // touching: nothing is closer, and a cap must be positive
    }
    if (found) return best;
    cap = std::numeric_limits<double>::infinity();
  }
  throw std::logic_error("viewer: the exact search found no closest pair");
}

}  // namespace

ViewerSummary writeViewerPage(const std::string& file, ViewerPage& page, std::size_t count,
                              const DescribeState& describe, double slack) {
  ViewerSummary summary;
  summary.states = count;
  summary.minClearance = std::numeric_limits<double>::infinity();
  DistanceScratch scratch;
  std::vector<CandidatePair> pairs;
  for (std::size_t i = 0; i < count; ++i) {
    ViewerState state;
    pairs.clear();
    describe(i, state, pairs);
    summary.minClearance = std::min(summary.minClearance, state.clearance);
    state.closest = closestPoints(pairs, state.clearance, slack, scratch, state.inside);
    page.states.push_back(std::move(state));
  }

  const std::string data = pageJson(page);
  const std::string title = htmlText(page.name);
  const std::string text = fillTemplate(viewer_assets::kViewerTemplate,
                                        {{"@ADSD_TITLE@", title},
                                         {"@ADSD_DATA@", data},
                                         {"@ADSD_THREE_CORE@", viewer_assets::kThreeCore},
                                         {"@ADSD_THREE_MODULE@", viewer_assets::kThreeModule},
                                         {"@ADSD_ORBIT_CONTROLS@", viewer_assets::kOrbitControls}});

  planner::writeOutputFile(file, "viewer page", [&](std::ostream& out) { out << text; });
  summary.bytes = text.size();
  return summary;
}

}  // namespace adsd::app
