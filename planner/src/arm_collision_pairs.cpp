#include "adsd/planner/arm_collision_pairs.h"

#include <cstdint>
#include <map>

#include <tinyxml.h>

#include "adsd/error.h"
#include "input_file.h"
#include "output_file.h"
#include "xml_input.h"

namespace adsd::planner {

ArmCollisionPairs::ArmCollisionPairs(const ArmModel& model)
    : links_(model.links.size()), enabled_(links_ * links_, false) {
  for (std::size_t a = 0; a < links_; ++a) {
    for (std::size_t b = 0; b < links_; ++b) {
      enabled_[a * links_ + b] = a != b && model.links[a].collision && model.links[b].collision;
    }
  }
  for (const auto& [a, b] : adjacentLinkPairs(model)) disable(a, b, "Adjacent");
}

void ArmCollisionPairs::disable(std::size_t a, std::size_t b, const std::string& reason) {
  if (a > b) std::swap(a, b);
  if (!enabled_[a * links_ + b]) return;
  enabled_[a * links_ + b] = enabled_[b * links_ + a] = false;
  disabled_.push_back({a, b, reason});
}

std::vector<std::pair<std::size_t, std::size_t>> ArmCollisionPairs::enabledPairs() const {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t a = 0; a < links_; ++a) {
    for (std::size_t b = a + 1; b < links_; ++b) {
      if (enabled_[a * links_ + b]) out.emplace_back(a, b);
    }
  }
  return out;
}

std::vector<std::pair<std::size_t, std::size_t>> adjacentLinkPairs(const ArmModel& model) {
  const std::size_t n = model.links.size();
  const auto bare = [&](std::size_t l) { return !model.links[l].collision; };
  const auto parentOf = [&](std::size_t l) -> std::int64_t {
    const int j = model.links[l].parentJoint;
    return j < 0 ? -1 : static_cast<std::int64_t>(model.joints[static_cast<std::size_t>(j)].parentLink);
  };
  // MoveIt's setup assistant (computeConnectionGraph): the kinematic tree's edges, parent and
  // child through any joint; then each link without geometry joins its neighbours to each other,
  // until nothing changes, so that two links whose only links between them have no geometry are
  // neighbours. Nothing else: a gripper fixed to a wrist is adjacent to the wrist only, and stays
  // checked against the forearm the wrist turns on, into which it can fold. Worked out whole: the
  // closure makes each connected run of bare links and every link touching it one set of mutual
  // neighbours (joining pair by pair took 6 s on a chain of 2000 bare links, an outside review).
  std::vector<bool> adjacent(n * n, false);
  const auto mark = [&](std::size_t a, std::size_t b) {
    if (a != b && !bare(a) && !bare(b)) adjacent[a * n + b] = adjacent[b * n + a] = true;
  };
  std::vector<std::size_t> run(n);  // union-find over the tree edges between bare links
  for (std::size_t l = 0; l < n; ++l) run[l] = l;
  const auto root = [&run](std::size_t l) {
    while (run[l] != l) l = run[l] = run[run[l]];
    return l;
  };
  for (std::size_t l = 0; l < n; ++l) {
    const std::int64_t parent = parentOf(l);
    if (parent < 0) continue;
    mark(l, static_cast<std::size_t>(parent));
    if (bare(l) && bare(static_cast<std::size_t>(parent))) run[root(l)] = root(static_cast<std::size_t>(parent));
  }
  // The links with geometry that touch each run of bare links, then each such set joined.
  std::vector<std::vector<std::size_t>> touching(n);
  for (std::size_t l = 0; l < n; ++l) {
    const std::int64_t parent = parentOf(l);
    if (parent < 0) continue;
    const auto p = static_cast<std::size_t>(parent);
    if (bare(l) && !bare(p)) touching[root(l)].push_back(p);
    if (!bare(l) && bare(p)) touching[root(p)].push_back(l);
  }
  for (const std::vector<std::size_t>& links : touching) {
    for (std::size_t i = 0; i < links.size(); ++i) {
      for (std::size_t k = i + 1; k < links.size(); ++k) mark(links[i], links[k]);
    }
  }
  // Rigid groups: a link joins its parent's group through a fixed joint (parents come first).
  // Their distance never changes, so a pair in one group is in contact in every state or in none
  // (MoveIt's sampling passes would call it "Always" or "Never"): checking it decides nothing.
  std::vector<std::size_t> group(n);
  for (std::size_t l = 0; l < n; ++l) {
    const int j = model.links[l].parentJoint;
    group[l] = (j >= 0 && model.joints[static_cast<std::size_t>(j)].type == ArmJointType::fixed)
                   ? group[model.joints[static_cast<std::size_t>(j)].parentLink]
                   : l;
  }
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t a = 0; a < n; ++a) {
    if (bare(a)) continue;
    for (std::size_t b = a + 1; b < n; ++b) {
      if (!bare(b) && (adjacent[a * n + b] || group[a] == group[b])) out.emplace_back(a, b);
    }
  }
  return out;
}

std::vector<std::string> disablePairsFromSrdf(const ArmModel& model, const std::string& srdfPath,
                                              ArmCollisionPairs& pairs) {
  const std::string text = readInputFile(srdfPath, "SRDF file");
  TiXmlDocument doc;
  xml::parseXml(srdfPath, text, doc);
  const TiXmlElement* robot = doc.FirstChildElement("robot");
  if (!robot) throw InputError(srdfPath + ": no <robot> element: not an SRDF file");
  // A URDF named as the SRDF has a <robot> too, and no <disable_collisions>: it was read as an
  // SRDF disabling nothing, without a word.
  if (const TiXmlElement* link = robot->FirstChildElement("link")) {
    throw InputError(srdfPath + ":" + std::to_string(link->Row()) +
                     ": a <link> element: this is a URDF, not an SRDF (which holds <disable_collisions>)");
  }
  std::vector<std::string> warnings;
  const char* name = robot->Attribute("name");
  if (name != nullptr && model.name != name) {
    warnings.push_back(srdfPath + ":" + std::to_string(robot->Row()) + ": the SRDF is for robot '" + name +
                       "', the URDF " + model.sourceFile + " is robot '" + model.name + "' (read on, as MoveIt does)");
  }
  // Links by name, looked up once per element: ArmModel::linkIndex scans the links, which for a
  // file of many elements on a robot of many links took time quadratic in them.
  std::map<std::string, std::size_t> linkByName;
  for (std::size_t l = 0; l < model.links.size(); ++l) linkByName.emplace(model.links[l].name, l);
  // A pair element's two links, as indices of the model.
  const auto linkPair = [&](const TiXmlElement* e) {
    const std::string where = srdfPath + ":" + std::to_string(e->Row());
    const char* link1 = e->Attribute("link1");
    const char* link2 = e->Attribute("link2");
    if (!link1 || !link2) throw InputError(where + ": <" + e->Value() + "> needs link1= and link2=");
    const auto first = linkByName.find(link1), second = linkByName.find(link2);
    if (first == linkByName.end() || second == linkByName.end()) {
      throw InputError(where + ": <" + e->Value() + "> names a link that " + model.sourceFile + " lacks ('" + link1 +
                       "', '" + link2 + "')");
    }
    return std::make_pair(first->second, second->second);
  };
  // MoveIt's allowed collision matrix from an SRDF: a link of <disable_default_collisions> is
  // unchecked against every other link but the pairs <enable_collisions> names, and the pairs of
  // <disable_collisions> are unchecked in any case (applied last).
  const std::size_t n = model.links.size();
  std::vector<bool> reenabled(n * n, false);
  for (const TiXmlElement* e = robot->FirstChildElement("enable_collisions"); e;
       e = e->NextSiblingElement("enable_collisions")) {
    const auto [a, b] = linkPair(e);
    reenabled[a * n + b] = reenabled[b * n + a] = true;
  }
  for (const TiXmlElement* e = robot->FirstChildElement("disable_default_collisions"); e;
       e = e->NextSiblingElement("disable_default_collisions")) {
    const std::string where = srdfPath + ":" + std::to_string(e->Row()) + ": <disable_default_collisions>";
    const char* link = e->Attribute("link");
    if (!link) throw InputError(where + " needs link=");
    const auto found = linkByName.find(link);
    if (found == linkByName.end()) {
      throw InputError(where + " names a link that " + model.sourceFile + " lacks ('" + link + "')");
    }
    const std::size_t a = found->second;
    for (std::size_t b = 0; b < n; ++b) {
      if (b != a && !reenabled[a * n + b]) pairs.disable(a, b, "SRDF default");
    }
  }
  for (const TiXmlElement* e = robot->FirstChildElement("disable_collisions"); e;
       e = e->NextSiblingElement("disable_collisions")) {
    const auto [a, b] = linkPair(e);
    const char* reason = e->Attribute("reason");
    if (a != b) pairs.disable(a, b, reason ? reason : "SRDF");
  }
  return warnings;
}

void writeSrdf(const ArmModel& model, const ArmCollisionPairs& pairs, const std::string& srdfPath) {
  TiXmlDocument doc;
  doc.LinkEndChild(new TiXmlDeclaration("1.0", "utf-8", ""));
  auto* robot = new TiXmlElement("robot");
  robot->SetAttribute("name", model.name);
  doc.LinkEndChild(robot);
  for (const ArmCollisionPairs::Disabled& d : pairs.disabled()) {
    auto* e = new TiXmlElement("disable_collisions");
    e->SetAttribute("link1", model.links[d.a].name);
    e->SetAttribute("link2", model.links[d.b].name);
    e->SetAttribute("reason", d.reason);
    robot->LinkEndChild(e);
  }
  TiXmlPrinter printer;
  doc.Accept(&printer);
  writeOutputFile(srdfPath, "SRDF file", [&](std::ostream& out) { out << printer.Str(); });
}

}  // namespace adsd::planner
