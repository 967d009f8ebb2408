// The sscc command-line tool: a thin shell over the library and its validation programs.
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "kernel_validation.hpp"
#include "selfccd_validation.hpp"

namespace {

const char* kUsage =
    "usage: sscc <command> [options]\n"
    "\n"
    "commands:\n"
    "  kernels   validate the vertex-face and edge-edge kernels\n"
    "            --queries DIR   the public CCD query set (e.g. ../shared/data/ccd-sample-queries)\n"
    "            --random N      N random queries of each kind (and N/10 near-degenerate ones)\n"
    "            --seed S        seed of the random queries (default 1)\n"
    "            --output DIR    CSV files and plots of the sweeps (default validation-output)\n"
    "            --repeats R     timing repeats, the median is reported (default 5)\n"
    "            --quiet         no progress output\n"
    "  selfccd   continuous self-collision over a seeded random trajectory\n"
    "            --mesh FILE            OFF, OBJ or PLY\n"
    "            --basis polynomial:R | FILE.U | FILE   (default polynomial:27)\n"
    "            --weights FILE         weights of the modes (default all 1)\n"
    "            --steps N --amplitude A --seed S   trajectory: ||q||_M stays near A\n"
    "            --methods LIST         comma-separated: traditional, exhaustive, fcl\n"
    "  help      this text\n";

[[noreturn]] void usage_error(const std::string& message) {
  std::cerr << "sscc: " << message << "\n\n" << kUsage;
  std::exit(2);
}

long parse_long(const std::string& flag, const std::string& value) {
  try {
    std::size_t used = 0;
    const long v = std::stol(value, &used);
    if (used != value.size() || v < 0) throw std::invalid_argument(value);
    return v;
  } catch (const std::exception&) {
    usage_error(flag + " expects a non-negative integer, got '" + value + "'");
  }
}

int run_kernels(const std::vector<std::string>& args) {
  sscc::validation::KernelValidationOptions options;
  bool quiet = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& flag = args[i];
    if (flag == "--quiet") {
      quiet = true;
      continue;
    }
    if (i + 1 >= args.size()) usage_error(flag + " needs a value (or is not an option)");
    const std::string& value = args[++i];
    if (flag == "--queries") {
      options.queries_dir = value;
    } else if (flag == "--random") {
      options.random = parse_long(flag, value);
    } else if (flag == "--seed") {
      options.seed = static_cast<std::uint64_t>(parse_long(flag, value));
    } else if (flag == "--output") {
      options.output_dir = value;
    } else if (flag == "--repeats") {
      options.repeats = static_cast<int>(parse_long(flag, value));
    } else {
      usage_error("unknown option '" + flag + "' for 'kernels'");
    }
  }
  if (options.queries_dir.empty() && options.random == 0) {
    usage_error("kernels needs --queries DIR or --random N");
  }
  std::ostream null_stream(nullptr);
  const long problems =
      sscc::validation::run_kernel_validation(options, std::cout, quiet ? null_stream : std::cerr);
  if (problems != 0) {
    std::cerr << "sscc kernels: " << problems << " disagreements with the ground truth\n";
    return 1;
  }
  return 0;
}

std::vector<std::string> split_list(const std::string& list) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = list.find(',', start);
    const std::string item = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (!item.empty()) items.push_back(item);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return items;
}

double parse_double(const std::string& flag, const std::string& value) {
  try {
    std::size_t used = 0;
    const double v = std::stod(value, &used);
    if (used != value.size() || !(v >= 0.0)) throw std::invalid_argument(value);
    return v;
  } catch (const std::exception&) {
    usage_error(flag + " expects a non-negative number, got '" + value + "'");
  }
}

int run_selfccd(const std::vector<std::string>& args) {
  sscc::validation::SelfCcdValidationOptions options;
  bool quiet = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& flag = args[i];
    if (flag == "--quiet") {
      quiet = true;
      continue;
    }
    if (i + 1 >= args.size()) usage_error(flag + " needs a value (or is not an option)");
    const std::string& value = args[++i];
    if (flag == "--mesh") {
      options.mesh = value;
    } else if (flag == "--basis") {
      options.basis = value;
    } else if (flag == "--weights") {
      options.weights = value;
    } else if (flag == "--steps") {
      options.steps = static_cast<int>(parse_long(flag, value));
    } else if (flag == "--amplitude") {
      options.amplitude = parse_double(flag, value);
    } else if (flag == "--seed") {
      options.seed = static_cast<std::uint64_t>(parse_long(flag, value));
    } else if (flag == "--methods") {
      options.methods = split_list(value);
    } else {
      usage_error("unknown option '" + flag + "' for 'selfccd'");
    }
  }
  if (options.mesh.empty()) usage_error("selfccd needs --mesh FILE");
  if (options.steps <= 0) usage_error("--steps must be positive");
  if (options.methods.empty()) usage_error("--methods needs at least one method");
  std::ostream null_stream(nullptr);
  const long problems =
      sscc::validation::run_selfccd_validation(options, std::cout, quiet ? null_stream : std::cerr);
  if (problems != 0) {
    std::cerr << "sscc selfccd: " << problems << " disagreements\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) usage_error("no command given");
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  try {
    if (command == "kernels") return run_kernels(args);
    if (command == "selfccd") return run_selfccd(args);
    if (command == "help" || command == "--help" || command == "-h") {
      std::cout << kUsage;
      return 0;
    }
    usage_error("unknown command '" + command + "'");
  } catch (const std::exception& e) {
    std::cerr << "sscc " << command << ": " << e.what() << '\n';
    return 1;
  }
}
