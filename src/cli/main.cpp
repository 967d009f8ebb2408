// The sscc command-line tool: a thin shell over the library and its validation programs.
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "kernel_validation.hpp"

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

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) usage_error("no command given");
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  try {
    if (command == "kernels") return run_kernels(args);
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
