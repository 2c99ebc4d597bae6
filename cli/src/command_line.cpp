#include "adsd/cli/command_line.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string_view>
#include <utility>

namespace adsd::cli {

po::typed_value<std::string>* value(const char* name) { return po::value<std::string>()->value_name(name); }

po::typed_value<std::vector<std::string>>* values(const char* name) {
  return po::value<std::vector<std::string>>()->value_name(name)->composing();
}

// ---- Arguments --------------------------------------------------------------------------------

std::optional<std::string> Arguments::text(const std::string& name) const {
  if (!has(name)) return std::nullopt;
  return map_[name].as<std::string>();
}

// /dev/stdout links to /proc/self/fd/1, which links to whatever the standard output was
// redirected to: the rename that puts an output in place replaced the link itself with a plain
// file (as root, the machine's /dev/stdout), and the redirection got nothing (an outside review).
bool inSystemTree(const std::string& file) {
  namespace fs = std::filesystem;
  auto system = [](const fs::path& p) {
    auto part = p.begin();
    if (part == p.end() || *part != p.root_path() || ++part == p.end()) return false;
    if (*part == "proc" || *part == "sys") return true;
    // /dev/shm is a plain file system (tmpfs) that programs share files in.
    return *part == "dev" && !(++part != p.end() && *part == "shm");
  };
  std::error_code ec;
  fs::path path = fs::absolute(file, ec);
  if (ec) return false;
  for (int hop = 0; hop < 40; ++hop) {  // the kernel's own limit on links followed
    const fs::path directory = fs::weakly_canonical(path.parent_path(), ec);
    if (ec) return false;
    path = directory / path.filename();
    if (system(path)) return true;
    if (!fs::is_symlink(path, ec)) return false;
    const fs::path target = fs::read_symlink(path, ec);
    if (ec) return false;
    path = target.is_absolute() ? target : directory / target;
  }
  return false;
}

std::optional<std::string> Arguments::outputFile(const std::string& name) const {
  const std::optional<std::string> file = text(name);
  if (!file) return std::nullopt;
  const std::string option = "--" + name + ": ";
  if (file->empty()) throw UsageError(option + "expected a file name, got ''");
  std::error_code ec;
  if (std::filesystem::is_directory(*file, ec)) throw UsageError(option + "'" + *file + "' is a directory, not a file");
  // The file is written through a temporary renamed over it: a device or a pipe there (/dev/null,
  // /dev/full) would be replaced by a plain file, and a write that should fail would seem done.
  const std::filesystem::file_status status = std::filesystem::status(*file, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    throw UsageError(option + "'" + *file + "' is a device, a pipe or a socket, not a file to write");
  }
  // A link there that leads to a plain file (/dev/stdout redirected into one) is a stream too.
  if (inSystemTree(*file)) {
    throw UsageError(option + "'" + *file + "' is in /dev, /proc or /sys (a device or a stream), not a file to write");
  }
  std::filesystem::path directory = std::filesystem::path(*file).parent_path();
  if (directory.empty()) directory = ".";
  if (!std::filesystem::is_directory(directory, ec)) {
    throw UsageError(option + "'" + *file + "': directory '" + directory.string() + "' does not exist");
  }
  // Written through a temporary name in the same directory (NAME.partial), then renamed: the
  // temporary's name must fit the file system's limit (a name of 250 bytes passed here and failed
  // once the work was done; an adversarial review), and the directory must be writable.
  const long nameMax = ::pathconf(directory.c_str(), _PC_NAME_MAX);
  const std::size_t longest = nameMax > 0 ? static_cast<std::size_t>(nameMax) : 255;
  const std::size_t nameBytes = std::filesystem::path(*file).filename().string().size();
  if (nameBytes + std::string_view(".partial").size() > longest) {
    throw UsageError(option + "'" + *file + "': the name is " + std::to_string(nameBytes) +
                     " bytes long; with '.partial' added for the temporary it is written under, it must fit " +
                     std::to_string(longest) + " bytes");
  }
  if (::access(directory.c_str(), W_OK) != 0) {
    throw UsageError(option + "'" + *file + "': directory '" + directory.string() + "' is not writable");
  }
  return file;
}

void requireDistinctFile(const std::string& option, const std::string& output,
                         const std::vector<std::pair<std::string, std::string>>& others) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path mine = fs::absolute(output, ec).lexically_normal();
  for (const auto& [what, file] : others) {
    const bool same = fs::exists(output, ec) && fs::exists(file, ec)
                          ? fs::equivalent(output, file, ec)
                          : mine == fs::absolute(file, ec).lexically_normal();
    if (same) {
      throw UsageError(option + ": '" + output + "' is " + what + " ('" + file + "'), not a file to write over");
    }
  }
}

std::vector<std::string> Arguments::texts(const std::string& name) const {
  if (!has(name)) return {};
  return map_[name].as<std::vector<std::string>>();
}

std::optional<std::uint64_t> Arguments::whole(const std::string& name, std::uint64_t min, std::uint64_t max) const {
  const std::optional<std::string> given = text(name);
  if (!given) return std::nullopt;
  return parseWhole(*given, "--" + name, min, max);
}

std::optional<double> Arguments::real(const std::string& name, const RealInterval& range) const {
  const std::optional<std::string> given = text(name);
  if (!given) return std::nullopt;
  return parseReal(*given, "--" + name, range);
}

std::optional<std::string> Arguments::choice(const std::string& name,
                                             std::initializer_list<std::string_view> choices) const {
  const std::optional<std::string> given = text(name);
  if (!given) return std::nullopt;
  if (std::find(choices.begin(), choices.end(), *given) != choices.end()) return given;
  std::string list;
  std::size_t i = 0;
  for (const std::string_view c : choices) {
    list += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + std::string(c);
    ++i;
  }
  throw UsageError("--" + name + ": expected " + list + ", got '" + *given + "'");
}

// ---- CommandLine ------------------------------------------------------------------------------

CommandLine::CommandLine(std::string program, std::string synopsis, std::string description, std::string details)
    : program_(std::move(program)),
      synopsis_(std::move(synopsis)),
      description_(std::move(description)),
      details_(std::move(details)),
      options_("options") {
  help_.add_options()("help,h", "print this help and exit");
}

void CommandLine::positional(const std::string& name) { positional_ = name; }

namespace {

/// Boost's default style without guessing an option from a prefix of its name.
constexpr int kStyle = po::command_line_style::default_style & ~po::command_line_style::allow_guessing;

/// Columns of the help's option list.
constexpr unsigned kHelpWidth = 100;

bool asksForHelp(const std::vector<std::string>& args) {
  for (const std::string& a : args) {
    if (a == "--") return false;  // what follows is arguments, not options
    if (a == "--help" || a == "-h") return true;
  }
  return false;
}

}  // namespace

std::optional<Arguments> CommandLine::parse(const std::vector<std::string>& args) const {
  po::options_description all;
  all.add(options_).add(help_);
  po::positional_options_description positional;
  if (positional_) all.add_options()(positional_->c_str(), po::value<std::vector<std::string>>());
  if (positional_) positional.add(positional_->c_str(), -1);

  po::variables_map map;
  try {
    po::store(po::command_line_parser(args).options(all).positional(positional).style(kStyle).run(), map);
    po::notify(map);
  } catch (const po::error& e) {
    // --help wins over whatever else is wrong on the line.
    if (asksForHelp(args)) {
      printHelp(std::cout);
      return std::nullopt;
    }
    // Boost's messages name the option ("unrecognised option '--x'", "the required argument for
    // option '--time' is missing"); a positional argument without a place is its own case.
    if (dynamic_cast<const po::too_many_positional_options_error*>(&e) != nullptr) {
      throw UsageError("unexpected argument (this command takes options only)");
    }
    throw UsageError(e.what());
  }
  if (map.count("help")) {
    printHelp(std::cout);
    return std::nullopt;
  }
  return Arguments(std::move(map));
}

void CommandLine::printHelp(std::ostream& out) const {
  // A group prints its own caption; the options are listed under "options:" once.
  // Wider than Boost's 80 columns, so that names like "--objective length|clearance" keep a gap
  // before their description.
  po::options_description listed(kHelpWidth, kHelpWidth / 2);
  for (const auto& option : options_.options()) listed.add(option);
  for (const auto& option : help_.options()) listed.add(option);
  out << "usage: " << synopsis_ << "\n\n" << description_ << "\n\noptions:\n" << listed;
  if (!details_.empty()) out << '\n' << details_;
  if (!details_.empty() && details_.back() != '\n') out << '\n';
}

int reportUsageError(const std::string& program, const UsageError& error) {
  std::cerr << program << ": error: " << error.what() << " (" << program << " --help)\n";
  return kUsageExitStatus;
}

int runProgram(const CommandLine& line, int argc, char** argv, const std::function<int(const Arguments&)>& run) {
  try {
    const std::optional<Arguments> given = line.parse(std::vector<std::string>(argv + 1, argv + argc));
    if (!given) return 0;
    return run(*given);
  } catch (const UsageError& e) {
    return reportUsageError(line.program(), e);
  }
}

}  // namespace adsd::cli
