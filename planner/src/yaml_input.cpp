#include "yaml_input.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

#include <locale.h>  // newlocale, strtod_l (POSIX): numbers read in the C locale
#include <stdlib.h>

#include <yaml-cpp/eventhandler.h>

#include "adsd/error.h"
#include "decimal_number.h"
#include "input_file.h"

namespace adsd::planner::yaml {

using adsd::planner::detail::isDecimalNumber;

namespace {

/// At most this many characters of a scalar are echoed in a message.
constexpr std::size_t kMaxEchoedCharacters = 60;

/// The budget of values a document may cost, per byte of its text and in all (Document's comment:
/// a file without aliases costs at most about one unit a byte; 4 leaves room, and the slack lets a
/// tiny file hold its few values).
constexpr std::size_t kBudgetPerByte = 4;
constexpr std::size_t kBudgetSlack = 1024;

const char* kindName(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Null: return "null";
    case YAML::NodeType::Scalar: return "a scalar";
    case YAML::NodeType::Sequence: return "a sequence";
    case YAML::NodeType::Map: return "a map";
    default: return "nothing";
  }
}

/// yaml-cpp keeps the first of two equal keys in a map and drops the second without a word (a
/// second `primitives:` or `position:` was silently ignored). Its parser's events show every key as
/// written, aliases unexpanded, so one linear pass over them finds a repeat.
class RepeatedKeyFinder : public YAML::EventHandler {
 public:
  explicit RepeatedKeyFinder(const std::string& source) : source_(source) {}

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override { takeSlot(); }
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override { takeSlot(); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string& value) override {
    if (!takeSlot()) return;
    const int line = mark.line + 1;  // yaml-cpp's marks are 0-based
    const auto [first, fresh] = open_.back().keyLines.emplace(value, line);
    if (!fresh) {
      throw InputError(source_ + ":" + std::to_string(line) + ": key " + quoted(value) +
                       " appears twice in one map (first at line " + std::to_string(first->second) + ")");
    }
  }
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    takeSlot();
    open_.push_back({false, true, {}});
  }
  void OnSequenceEnd() override { open_.pop_back(); }
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    takeSlot();
    open_.push_back({true, true, {}});
  }
  void OnMapEnd() override { open_.pop_back(); }

 private:
  struct Collection {
    bool isMap;
    bool nextIsKey;                       ///< a map's nodes alternate key, value
    std::map<std::string, int> keyLines;  ///< scalar key -> its line
  };

  /// A node begins in the innermost open collection: true when it is a map's key.
  bool takeSlot() {
    if (open_.empty() || !open_.back().isMap) return false;
    const bool isKey = open_.back().nextIsKey;
    open_.back().nextIsKey = !isKey;
    return isKey;
  }

  const std::string& source_;
  std::vector<Collection> open_;
};

/// Whether a document holds anything (a null alone is an empty document, as `---` at the end of a
/// file gives), and the line where it begins.
class DocumentContent : public YAML::EventHandler {
 public:
  bool found = false;
  int line = 0;

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { note(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string&) override { note(mark); }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    note(mark);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    note(mark);
  }
  void OnMapEnd() override {}

 private:
  void note(const YAML::Mark& mark) {
    if (found) return;
    found = true;
    line = mark.line + 1;  // yaml-cpp's marks are 0-based
  }
};

}  // namespace

namespace {

/// \p text with its control characters as '?': the file's text in a one-line message.
std::string printable(std::string text) {
  for (char& c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) c = '?';
  }
  return text;
}

}  // namespace

std::string quoted(const std::string& text) {
  return "'" + printable(text.size() <= kMaxEchoedCharacters ? text : text.substr(0, kMaxEchoedCharacters) + "...") +
         "'";
}

Document::Document(const std::string& text, std::string source)
    : source_(std::move(source)), budget_(kBudgetPerByte * text.size() + kBudgetSlack) {
  requireNarrowText(text, source_);
  // yaml-cpp's errors as ours, at their line (a mark of -1: the parser did not know the place).
  const auto refuse = [this](const YAML::Exception& e) {
    const std::string line = e.mark.line >= 0 ? ":" + std::to_string(e.mark.line + 1) : "";
    std::string what = e.msg;
    for (char& c : what) {
      if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    }
    throw InputError(source_ + line + ": not valid YAML: " + what);
  };
  try {
    root_ = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    refuse(e);
  }
  std::istringstream events(text);
  YAML::Parser parser(events);
  RepeatedKeyFinder finder(source_);
  parser.HandleNextDocument(finder);
  // One document per file: the readers take the first, and a second was dropped in silence (an
  // outside review). An empty one after a `---` is no second: `rostopic echo` ends each message so.
  // Broken, it is named as the first would be (it was an internal error: an outside review). One
  // more document is read, by events: yaml-cpp 0.7's LoadAll never ended on ",a# " (the fuzzer).
  DocumentContent second;
  try {
    parser.HandleNextDocument(second);
  } catch (const YAML::Exception& e) {
    refuse(e);
  }
  if (second.found) {
    throw InputError(source_ + ":" + std::to_string(second.line) +
                     ": a second YAML document (after '---'): the file holds one");
  }
}

Field Document::root() const {
  return Field{root_, "", 1};
}

void Document::fail(const Field& f, const std::string& what) const {
  // A key is the file's text: a line end in a quoted key broke the one-line message (the fuzzer).
  const std::string field = f.path.empty() ? "the document" : "field '" + printable(f.path) + "'";
  throw InputError(source_ + ":" + std::to_string(f.line) + ": " + field + ": " + what);
}

void Document::requireMap(const Field& f) const {
  if (!f.node.IsDefined()) fail(f, "is missing");
  if (!f.node.IsMap()) fail(f, std::string("expected a map, got ") + kindName(f.node));
}

std::vector<Field> Document::keysOutside(const Field& map, std::initializer_list<const char*> known) const {
  requireMap(map);
  std::vector<Field> outside;
  for (auto it = map.node.begin(); it != map.node.end(); ++it) {
    // Copies: the iterator's pair is a temporary, and a reference into it dangled (AddressSanitizer).
    const YAML::Node key = it->first;
    const YAML::Node value = it->second;
    Field f{value, map.path, static_cast<int>(key.Mark().line) + 1};
    if (f.line < 1) f.line = map.line;
    if (!key.IsScalar()) fail(f, "a key that is not a name");
    const std::string name = key.Scalar();
    if (std::find_if(known.begin(), known.end(), [&](const char* k) { return name == k; }) != known.end()) continue;
    f.path = map.path.empty() ? name : map.path + "." + name;
    outside.push_back(std::move(f));
  }
  return outside;
}

Field Document::child(const Field& map, const std::string& key) const {
  requireMap(map);
  const YAML::Node& parent = map.node;
  // Copy-constructed, never assigned: assigning a yaml-cpp node rebinds what it refers to, and
  // assigning an absent (zombie) node throws.
  Field c{parent[key], map.path.empty() ? key : map.path + "." + key, 0};
  c.line = c.node.IsDefined() ? static_cast<int>(c.node.Mark().line) + 1 : map.line;
  if (c.line < 1) c.line = map.line;
  return c;
}

Field Document::required(const Field& map, const std::string& key) const {
  Field c = child(map, key);
  if (!c.node.IsDefined()) fail(c, "is missing");
  return c;
}

std::size_t Document::sequenceLength(const Field& f) const {
  if (!f.node.IsDefined()) fail(f, "is missing");
  if (!f.node.IsSequence()) fail(f, std::string("expected a sequence, got ") + kindName(f.node));
  return f.node.size();
}

Field Document::element(const Field& sequence, std::size_t i) const {
  const YAML::Node& parent = sequence.node;
  Field c{parent[i], sequence.path + "[" + std::to_string(i) + "]", 0};
  c.line = c.node.IsDefined() ? static_cast<int>(c.node.Mark().line) + 1 : sequence.line;
  if (c.line < 1) c.line = sequence.line;
  spend(c);
  return c;
}

void Document::spend(const Field& f) const {
  if (++spent_ > budget_) {
    fail(f, "more values than a file of " + std::to_string((budget_ - kBudgetSlack) / kBudgetPerByte) +
                " bytes can hold (YAML aliases repeating nodes?); refused");
  }
}

std::string Document::text(const Field& f) const {
  if (!f.node.IsDefined()) fail(f, "is missing");
  if (!f.node.IsScalar()) fail(f, std::string("expected a scalar, got ") + kindName(f.node));
  spend(f);
  return f.node.Scalar();
}

double Document::number(const Field& f) const {
  const std::string v = text(f);
  // The C locale's reading whatever the process's locale (a program under a decimal-comma locale
  // must read "0.5" as a half).
  static const locale_t classic = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
  if (!isDecimalNumber(v)) fail(f, "expected a finite number, got " + quoted(v));
  char* end = nullptr;
  const double x = strtod_l(v.c_str(), &end, classic);
  if (end != v.c_str() + v.size() || !std::isfinite(x)) fail(f, "expected a finite number, got " + quoted(v));
  return x;
}

std::uint64_t Document::whole(const Field& f, std::uint64_t most) const {
  const std::string v = text(f);
  const bool digits = !v.empty() && v.size() <= 19 &&
                      std::all_of(v.begin(), v.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
  if (!digits) fail(f, "expected a whole number from 0 to " + std::to_string(most) + ", got " + quoted(v));
  const std::uint64_t x = std::strtoull(v.c_str(), nullptr, 10);
  if (x > most) fail(f, quoted(v) + " is out of range (at most " + std::to_string(most) + ")");
  return x;
}

Vec3 Document::point(const Field& f) const {
  if (!f.node.IsDefined()) return Vec3::Zero();
  Vec3 p;
  if (f.node.IsSequence()) {
    if (f.node.size() != 3) fail(f, "expected 3 coordinates [x, y, z], got " + std::to_string(f.node.size()));
    for (int i = 0; i < 3; ++i) p[i] = number(element(f, static_cast<std::size_t>(i)));
  } else {
    // A key other than x, y, z is a mistyped one (`yy:`), whose coordinate would silently be 0.
    if (const std::vector<Field> other = keysOutside(f, {"x", "y", "z"}); !other.empty()) {
      fail(other.front(), "not a coordinate of a point (x, y, z)");
    }
    const char* names[] = {"x", "y", "z"};
    // A coordinate left out of a map is 0, as in a ROS message.
    for (int i = 0; i < 3; ++i) {
      const Field c = child(f, names[i]);
      p[i] = c.node.IsDefined() ? number(c) : 0.0;
    }
  }
  if (p.cwiseAbs().maxCoeff() > kMaxSceneCoordinate) fail(f, "a coordinate beyond 1e6 in magnitude");
  return p;
}

Eigen::Quaterniond Document::quaternion(const Field& f) const {
  if (!f.node.IsDefined()) return Eigen::Quaterniond::Identity();
  double q[4];
  if (f.node.IsSequence()) {
    if (f.node.size() != 4) fail(f, "expected 4 components [x, y, z, w], got " + std::to_string(f.node.size()));
    for (int i = 0; i < 4; ++i) q[i] = number(element(f, static_cast<std::size_t>(i)));
  } else {
    // `W: 1` for `w: 1` left w at 0, and (1, 0, 0, 0) passed the unit check: a half turn about x
    // in place of a quarter turn.
    if (const std::vector<Field> other = keysOutside(f, {"x", "y", "z", "w"}); !other.empty()) {
      fail(other.front(), "not a component of a quaternion (x, y, z, w)");
    }
    const char* names[] = {"x", "y", "z", "w"};
    for (int i = 0; i < 4; ++i) {
      const Field c = child(f, names[i]);
      q[i] = c.node.IsDefined() ? number(c) : 0.0;
    }
  }
  // Each component is finite; scaled by the largest before squaring, so that 1e300 does not overflow.
  const double largest = std::max({std::fabs(q[0]), std::fabs(q[1]), std::fabs(q[2]), std::fabs(q[3])});
  if (largest == 0.0) fail(f, "the quaternion is zero");
  const Eigen::Vector4d scaled(q[0] / largest, q[1] / largest, q[2] / largest, q[3] / largest);
  const double norm = scaled.norm() * largest;
  if (!(std::fabs(norm - 1.0) <= kQuaternionNormTolerance)) {
    fail(f, "the quaternion's norm is " + std::to_string(norm) + ", not 1 (within 1e-3)");
  }
  return Eigen::Quaterniond(scaled[3], scaled[0], scaled[1], scaled[2]).normalized();
}

Pose Document::pose(const Field& f) const {
  Pose p = Pose::Identity();
  if (!f.node.IsDefined()) return p;
  requireMap(f);
  // `orientaton:` or `positon:` left the object unturned or at the origin without a word (an
  // outside review): a geometry_msgs/Pose has these two fields and no other.
  if (const std::vector<Field> other = keysOutside(f, {"position", "orientation"}); !other.empty()) {
    fail(other.front(), "not a field of a pose (position, orientation)");
  }
  p.translate(point(child(f, "position")));
  p.rotate(quaternion(child(f, "orientation")));
  return p;
}

JointValues jointState(const Document& doc, const Field& state) {
  JointValues out;
  const Field names = doc.child(state, "name");
  const Field positions = doc.child(state, "position");
  const std::size_t n = names.node.IsDefined() ? doc.sequenceLength(names) : 0;
  const std::size_t m = positions.node.IsDefined() ? doc.sequenceLength(positions) : 0;
  if (n != m) {
    doc.fail(positions.node.IsDefined() ? positions : names,
             std::to_string(m) + " positions for " + std::to_string(n) + " joint names");
  }
  std::map<std::string, int> nameLines;  // the repeat is named by the line of the first name, not its position
  for (std::size_t i = 0; i < n; ++i) {
    const Field name = doc.element(names, i);
    const std::string joint = doc.text(name);
    if (joint.empty()) doc.fail(name, "an empty joint name");
    const Field position = doc.element(positions, i);
    const double value = doc.number(position);
    if (const auto [first, fresh] = nameLines.emplace(joint, name.line); !fresh) {
      doc.fail(name, "joint " + quoted(joint) + " appears twice (first at line " + std::to_string(first->second) + ")");
    }
    out.values.emplace(joint, value);
    out.lines[joint] = position.line;
  }
  return out;
}

}  // namespace adsd::planner::yaml
