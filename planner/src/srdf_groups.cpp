#include "adsd/planner/srdf_groups.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include <tinyxml.h>

#include "adsd/error.h"
#include "input_file.h"
#include "xml_input.h"

namespace adsd::planner {

namespace {

/// How deep groups may include groups. MoveIt's SRDF files nest two or three; a chain of 30 000
/// groups each including the next crashed the expansion's recursion (stack overflow).
constexpr std::size_t kMaxGroupNesting = 100;

/// One SRDF's groups expanded into joints (collect), with the file's group elements and the
/// model's joints and links indexed by name once: looked up by a scan each, a file of many groups
/// or entries took time quadratic in them (30 000 nested groups: 40 s before the crash).
class GroupExpansion {
 public:
  GroupExpansion(const ArmModel& model, const std::string& srdfPath, const TiXmlElement* robot)
      : model_(model), srdfPath_(srdfPath) {
    for (const TiXmlElement* g = robot->FirstChildElement("group"); g; g = g->NextSiblingElement("group")) {
      const char* n = g->Attribute("name");
      if (n == nullptr) continue;
      const auto [it, fresh] = groups_.emplace(n, Definitions{g, nullptr});
      if (!fresh && it->second.second == nullptr) it->second.second = g;
    }
    for (std::size_t j = 0; j < model.joints.size(); ++j) joints_.emplace(model.joints[j].name, j);
    for (std::size_t l = 0; l < model.links.size(); ++l) links_.emplace(model.links[l].name, l);
  }

  /// The <group> element named \p name, or null; two of that name are an error at the second's
  /// line (the first was taken in silence: an outside review).
  const TiXmlElement* find(const std::string& name) const {
    const auto it = groups_.find(name);
    if (it == groups_.end()) return nullptr;
    if (it->second.second != nullptr) {
      throw InputError(srdfPath_ + ":" + std::to_string(it->second.second->Row()) + ": group '" + name +
                       "' is defined again (first at line " + std::to_string(it->second.first->Row()) + ")");
    }
    return it->second.first;
  }

  /// Collects into \p joints (indices into model.joints) what group element \p group, named
  /// \p name, names. \p open holds the groups being expanded, to refuse groups that include each
  /// other; a group expanded once is not expanded again (a group included twice by each of a
  /// chain of groups was expanded 2^n times).
  void collect(const std::string& name, const TiXmlElement* group, std::set<std::string>& open,
               std::set<std::size_t>& joints) {
    if (!expanded_.insert(name).second) return;
    for (const TiXmlElement* e = group->FirstChildElement(); e; e = e->NextSiblingElement()) {
      const std::string kind = e->ValueStr();
      if (kind == "joint") {
        joints.insert(jointNamed(e, attribute(e, "name")));
      } else if (kind == "link") {
        const int parent = model_.links[linkNamed(e, attribute(e, "name"))].parentJoint;
        if (parent >= 0) joints.insert(static_cast<std::size_t>(parent));
      } else if (kind == "chain") {
        collectChain(e, joints);
      } else if (kind == "group") {
        const std::string sub = attribute(e, "name");
        const TiXmlElement* element = find(sub);
        if (element == nullptr) throw InputError(where(e) + "group names group '" + sub + "', which the file lacks");
        if (!open.insert(sub).second) throw InputError(where(e) + "groups include each other (group '" + sub + "')");
        if (open.size() > kMaxGroupNesting + 1) {  // the group asked for and the ones it includes
          throw InputError(where(e) + "groups include groups more than " + std::to_string(kMaxGroupNesting) +
                           " deep");
        }
        collect(sub, element, open, joints);
        open.erase(sub);
      }
    }
  }

 private:
  using Definitions = std::pair<const TiXmlElement*, const TiXmlElement*>;  ///< the first and a second

  std::string where(const TiXmlElement* e) const { return srdfPath_ + ":" + std::to_string(e->Row()) + ": "; }

  std::string attribute(const TiXmlElement* e, const char* name) const {
    const char* value = e->Attribute(name);
    if (value == nullptr) throw InputError(where(e) + "<" + e->ValueStr() + "> needs " + name + "=");
    return value;
  }

  std::size_t jointNamed(const TiXmlElement* e, const std::string& name) const {
    const auto it = joints_.find(name);
    if (it == joints_.end()) {
      throw InputError(where(e) + "group names joint '" + name + "', which " + model_.sourceFile + " lacks");
    }
    return it->second;
  }

  std::size_t linkNamed(const TiXmlElement* e, const std::string& name) const {
    const auto it = links_.find(name);
    if (it == links_.end()) {
      throw InputError(where(e) + "group names link '" + name + "', which " + model_.sourceFile + " lacks");
    }
    return it->second;
  }

  /// The joints on the tree's path between a chain's two links: up from the tip to the first link
  /// the base is below (the base itself for an arm's chain), and up from the base to that link. A
  /// chain from one hand to the other goes through the torso, as in MoveIt (an outside review: it
  /// was refused, the tip not being below the base).
  void collectChain(const TiXmlElement* e, std::set<std::size_t>& joints) const {
    const std::size_t base = linkNamed(e, attribute(e, "base_link"));
    const std::size_t tip = linkNamed(e, attribute(e, "tip_link"));
    const auto up = [this](std::size_t link) {
      const int parent = model_.links[link].parentJoint;
      return parent < 0 ? link : model_.joints[static_cast<std::size_t>(parent)].parentLink;
    };
    std::set<std::size_t> aboveBase = {base};
    for (std::size_t link = base; model_.links[link].parentJoint >= 0;) aboveBase.insert(link = up(link));
    std::size_t meet = tip;
    while (!aboveBase.count(meet)) {
      const int parent = model_.links[meet].parentJoint;
      if (parent < 0) {  // readUrdf leaves one root, so the two always meet
        throw InputError(where(e) + "chain: links '" + model_.links[tip].name + "' and '" + model_.links[base].name +
                         "' are in no one tree");
      }
      joints.insert(static_cast<std::size_t>(parent));
      meet = up(meet);
    }
    for (std::size_t link = base; link != meet; link = up(link)) {
      joints.insert(static_cast<std::size_t>(model_.links[link].parentJoint));
    }
  }

  const ArmModel& model_;
  const std::string& srdfPath_;
  std::map<std::string, Definitions> groups_;
  std::map<std::string, std::size_t> joints_, links_;
  std::set<std::string> expanded_;
};

}  // namespace

std::optional<std::vector<std::string>> srdfGroupJoints(const ArmModel& model, const std::string& srdfPath,
                                                        const std::string& group) {
  const std::string text = readInputFile(srdfPath, "SRDF file");
  TiXmlDocument doc;
  xml::parseXml(srdfPath, text, doc);
  const TiXmlElement* robot = doc.FirstChildElement("robot");
  if (!robot) throw InputError(srdfPath + ": no <robot> element: not an SRDF file");
  GroupExpansion expansion(model, srdfPath, robot);
  const TiXmlElement* element = expansion.find(group);
  if (element == nullptr) return std::nullopt;
  std::set<std::string> open = {group};
  std::set<std::size_t> joints;
  expansion.collect(group, element, open, joints);
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
