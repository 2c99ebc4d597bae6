#include "adsd/planner/arm_collision_pairs.h"

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
  // MoveIt's setup assistant (computeConnectionGraph): the kinematic tree's edges, parent and
  // child through any joint; then each link without geometry joins its neighbours to each other,
  // until nothing changes, so that two links whose only link between them has no geometry are
  // neighbours. Nothing else: a gripper fixed to a wrist is adjacent to the wrist only, and stays
  // checked against the forearm the wrist turns on, into which it can fold.
  std::vector<std::vector<bool>> neighbours(n, std::vector<bool>(n, false));
  for (std::size_t l = 0; l < n; ++l) {
    const int j = model.links[l].parentJoint;
    if (j < 0) continue;
    const std::size_t parent = model.joints[static_cast<std::size_t>(j)].parentLink;
    neighbours[l][parent] = neighbours[parent][l] = true;
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t bare = 0; bare < n; ++bare) {
      if (model.links[bare].collision) continue;
      for (std::size_t a = 0; a < n; ++a) {
        if (!neighbours[bare][a]) continue;
        for (std::size_t b = a + 1; b < n; ++b) {
          if (!neighbours[bare][b] || neighbours[a][b]) continue;
          neighbours[a][b] = neighbours[b][a] = true;
          changed = true;
        }
      }
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
    for (std::size_t b = a + 1; b < n; ++b) {
      if (neighbours[a][b] || group[a] == group[b]) out.emplace_back(a, b);
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
  for (const TiXmlElement* e = robot->FirstChildElement("disable_collisions"); e;
       e = e->NextSiblingElement("disable_collisions")) {
    const std::string where = srdfPath + ":" + std::to_string(e->Row());
    const char* link1 = e->Attribute("link1");
    const char* link2 = e->Attribute("link2");
    if (!link1 || !link2) throw InputError(where + ": <disable_collisions> needs link1= and link2=");
    std::size_t a = 0, b = 0;
    try {
      a = model.linkIndex(link1);
      b = model.linkIndex(link2);
    } catch (const InputError&) {
      throw InputError(where + ": <disable_collisions> names a link that " + model.sourceFile + " lacks ('" + link1 +
                       "', '" + link2 + "')");
    }
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
