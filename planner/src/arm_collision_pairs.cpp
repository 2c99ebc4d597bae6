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
  // Rigid groups: a link joins its parent's group through a fixed joint (parents come first).
  std::vector<std::size_t> group(n);
  for (std::size_t l = 0; l < n; ++l) {
    const int j = model.links[l].parentJoint;
    group[l] = (j >= 0 && model.joints[static_cast<std::size_t>(j)].type == ArmJointType::fixed)
                   ? group[model.joints[static_cast<std::size_t>(j)].parentLink]
                   : l;
  }
  // The group each group hangs from through its movable joint (its first link's parent's group).
  std::vector<std::size_t> parentGroup(n, n);
  for (std::size_t l = 0; l < n; ++l) {
    const int j = model.links[l].parentJoint;
    if (group[l] == l && j >= 0) parentGroup[l] = group[model.joints[static_cast<std::size_t>(j)].parentLink];
  }
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      const int jb = model.links[b].parentJoint;  // b > a: b may be a's child, never its parent
      const bool parentChild = jb >= 0 && model.joints[static_cast<std::size_t>(jb)].parentLink == a;
      const bool sameGroup = group[a] == group[b];
      const bool groupsJoined = parentGroup[group[b]] == group[a] || parentGroup[group[a]] == group[b];
      if (parentChild || sameGroup || groupsJoined) out.emplace_back(a, b);
    }
  }
  return out;
}

void disablePairsFromSrdf(const ArmModel& model, const std::string& srdfPath, ArmCollisionPairs& pairs) {
  const std::string text = readInputFile(srdfPath, "SRDF file");
  TiXmlDocument doc;
  xml::parseXml(srdfPath, text, doc);
  const TiXmlElement* robot = doc.FirstChildElement("robot");
  if (!robot) throw InputError(srdfPath + ": no <robot> element: not an SRDF file");
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
