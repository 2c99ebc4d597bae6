#include "adsd/planner/srdf_groups.h"

#include <algorithm>
#include <set>

#include <tinyxml.h>

#include "adsd/error.h"
#include "input_file.h"
#include "xml_input.h"

namespace adsd::planner {

namespace {

/// The <group> element named \p name under \p robot, or null; two of that name are an error at
/// the second's line of \p srdfPath (the first was taken in silence: an outside review).
const TiXmlElement* findGroup(const std::string& srdfPath, const TiXmlElement* robot, const std::string& name) {
  const TiXmlElement* found = nullptr;
  for (const TiXmlElement* g = robot->FirstChildElement("group"); g; g = g->NextSiblingElement("group")) {
    const char* n = g->Attribute("name");
    if (n == nullptr || name != n) continue;
    if (found != nullptr) {
      throw InputError(srdfPath + ":" + std::to_string(g->Row()) + ": group '" + name + "' is defined again (first at line " +
                       std::to_string(found->Row()) + ")");
    }
    found = g;
  }
  return found;
}

/// Collects into \p joints (indices into model.joints) what group element \p group names;
/// \p open holds the groups being expanded, to refuse groups that include each other.
void collectGroup(const ArmModel& model, const std::string& srdfPath, const TiXmlElement* robot,
                  const TiXmlElement* group, std::set<std::string>& open, std::set<std::size_t>& joints) {
  const auto where = [&](const TiXmlElement* e) { return srdfPath + ":" + std::to_string(e->Row()) + ": "; };
  const auto attribute = [&](const TiXmlElement* e, const char* name) {
    const char* value = e->Attribute(name);
    if (value == nullptr) throw InputError(where(e) + "<" + e->ValueStr() + "> needs " + name + "=");
    return std::string(value);
  };
  const auto jointNamed = [&](const TiXmlElement* e, const std::string& name) {
    for (std::size_t j = 0; j < model.joints.size(); ++j) {
      if (model.joints[j].name == name) return j;
    }
    throw InputError(where(e) + "group names joint '" + name + "', which " + model.sourceFile + " lacks");
  };
  const auto linkNamed = [&](const TiXmlElement* e, const std::string& name) {
    for (std::size_t l = 0; l < model.links.size(); ++l) {
      if (model.links[l].name == name) return l;
    }
    throw InputError(where(e) + "group names link '" + name + "', which " + model.sourceFile + " lacks");
  };
  for (const TiXmlElement* e = group->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string kind = e->ValueStr();
    if (kind == "joint") {
      joints.insert(jointNamed(e, attribute(e, "name")));
    } else if (kind == "link") {
      const int parent = model.links[linkNamed(e, attribute(e, "name"))].parentJoint;
      if (parent >= 0) joints.insert(static_cast<std::size_t>(parent));
    } else if (kind == "chain") {
      // The joints on the tree's path between the two links: up from the tip to the first link
      // the base is below (the base itself for an arm's chain), and up from the base to that
      // link. A chain from one hand to the other goes through the torso, as in MoveIt (an outside
      // review: it was refused, the tip not being below the base).
      const std::size_t base = linkNamed(e, attribute(e, "base_link"));
      const std::size_t tip = linkNamed(e, attribute(e, "tip_link"));
      const auto up = [&model](std::size_t link) {
        const int parent = model.links[link].parentJoint;
        return parent < 0 ? link : model.joints[static_cast<std::size_t>(parent)].parentLink;
      };
      std::set<std::size_t> aboveBase = {base};
      for (std::size_t link = base; model.links[link].parentJoint >= 0;) aboveBase.insert(link = up(link));
      std::size_t meet = tip;
      while (!aboveBase.count(meet)) {
        const int parent = model.links[meet].parentJoint;
        if (parent < 0) {  // readUrdf leaves one root, so the two always meet
          throw InputError(where(e) + "chain: links '" + model.links[tip].name + "' and '" + model.links[base].name +
                           "' are in no one tree");
        }
        joints.insert(static_cast<std::size_t>(parent));
        meet = up(meet);
      }
      for (std::size_t link = base; link != meet; link = up(link)) {
        joints.insert(static_cast<std::size_t>(model.links[link].parentJoint));
      }
    } else if (kind == "group") {
      const std::string name = attribute(e, "name");
      const TiXmlElement* sub = findGroup(srdfPath, robot, name);
      if (sub == nullptr) throw InputError(where(e) + "group names group '" + name + "', which the file lacks");
      if (!open.insert(name).second) throw InputError(where(e) + "groups include each other (group '" + name + "')");
      collectGroup(model, srdfPath, robot, sub, open, joints);
      open.erase(name);
    }
  }
}

}  // namespace

std::optional<std::vector<std::string>> srdfGroupJoints(const ArmModel& model, const std::string& srdfPath,
                                                        const std::string& group) {
  const std::string text = readInputFile(srdfPath, "SRDF file");
  TiXmlDocument doc;
  xml::parseXml(srdfPath, text, doc);
  const TiXmlElement* robot = doc.FirstChildElement("robot");
  if (!robot) throw InputError(srdfPath + ": no <robot> element: not an SRDF file");
  const TiXmlElement* element = findGroup(srdfPath, robot, group);
  if (element == nullptr) return std::nullopt;
  std::set<std::string> open = {group};
  std::set<std::size_t> joints;
  collectGroup(model, srdfPath, robot, element, open, joints);
  std::vector<std::string> names;
  for (const std::size_t i : model.activeJoints) {
    if (joints.count(i) != 0) names.push_back(model.joints[i].name);
  }
  // Nothing to plan is a mistake in the file: planning every joint instead, as without a group,
  // would move what the user meant to hold.
  if (names.empty()) {
    throw InputError(srdfPath + ":" + std::to_string(element->Row()) + ": group '" + group +
                     "' names no movable joint of robot '" + model.name + "'");
  }
  return names;
}

}  // namespace adsd::planner
