// The sscc command-line tool: a thin shell over the library and its validation programs.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <initializer_list>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "basis_command.hpp"
#include "bench/bench_command.hpp"
#include "certificate_sweep.hpp"
#include "decimate_command.hpp"
#include "demo/demo_command.hpp"
#include "kernel_seed_range.hpp"
#include "kernel_validation.hpp"
#include "poses_command.hpp"
#include "precompute_command.hpp"
#include "scale_command.hpp"
#include "selfccd_validation.hpp"
#include "sscc/threads.hpp"
#include "stress/stress_command.hpp"

namespace {

const char* kUsage =
    "usage: sscc <command> [options] [--threads N]\n"
    "\n"
    "  --threads N: every command uses N threads (default: every core, or OMP_NUM_THREADS);\n"
    "  the reports do not depend on it.\n"
    "\n"
    "commands:\n"
    "  kernels   validate the vertex-face and edge-edge kernels\n"
    "            --queries DIR   the public CCD query set (e.g. ../shared/data/ccd-sample-queries)\n"
    "            --random N      N random queries of each kind (and N/10 near-degenerate, integer-grid\n"
    "                            and resting-contact ones, timed per query and per stage)\n"
    "            --seed S        seed of the random queries (default 1)\n"
    "            --output DIR    CSV files and plots of the sweeps (default validation-output)\n"
    "            --repeats R     timing repeats, the median is reported (default 5)\n"
    "            --search-slow N hill-climb N steps per kind for the slowest query\n"
    "            --exponent-range E  coordinates the search makes stay within 2^-E..2^E (default 1074)\n"
    "            --separation-only   with --random: only the minimum-separation sweep, on the same queries\n"
    "            --seeds A:B     instead: the check against the exact reference of seeds A..B-1, each\n"
    "                            seed its own queries (--per-seed N random ones of each kind, default\n"
    "                            1000, and N/10 near-degenerate), so that ranges split a long run:\n"
    "                            the counts of A:B and B:C add up to those of A:C\n"
    "            --quiet         no progress output\n"
    "  precompute  the certificates of a model, written to a certificate file\n"
    "            --mesh FILE --basis B --weights FILE   the model, as for selfccd\n"
    "            --epsilon E            relative accuracy of the radii (default 0.1)\n"
    "            --global-scale G       radii resolved up to G times the global radius (default 1)\n"
    "            --output FILE.sscc     the certificate file\n"
    "            --shard I/N            only shard I of N (0 <= I < N): the subtrees below a split\n"
    "                                   depth dealt to N processes or machines; --output then\n"
    "                                   names the shard file (FILE.sscc-part), for merge\n"
    "  merge     the certificate file from the shard files of precompute --shard, byte for byte\n"
    "            the one precompute writes (the levels above the split depth are computed here)\n"
    "            --mesh FILE --basis B --weights FILE   the model, as for precompute\n"
    "            --output FILE.sscc     the certificate file\n"
    "            SHARD-FILE ...         the N shard files, in any order\n"
    "  certificates  run time against error of the certificates: for each epsilon, precompute,\n"
    "            then SSCC against the traditional query on one trajectory (CSV and plot)\n"
    "            --mesh FILE --basis B --weights FILE   the model\n"
    "            --epsilons LIST        default 0.5,0.2,0.1,0.05,0.02,0.01\n"
    "            --steps N --amplitude A --burst B --seed S   the trajectory, as for selfccd\n"
    "            --output DIR           CSV and plot (default validation-output)\n"
    "  basis     a subspace basis for a mesh, written as a Vega .U file and its weights\n"
    "            --mesh FILE            OFF, OBJ or PLY\n"
    "            --method M             modal (linear modal analysis, weights omega^2/2),\n"
    "                                   polynomial (the 27 linear and quadratic modes),\n"
    "                                   stiffness (stiffness-scale the basis given by --input), or\n"
    "                                   pca (principal components of --poses, weights 1/variance)\n"
    "            --modes R              modes wanted (default 30; polynomial: at most 27;\n"
    "                                   pca: default by --variance)\n"
    "            --poses LIST           pca: comma-separated pose meshes (the connectivity of\n"
    "                                   --mesh) or directories of them\n"
    "            --variance F           pca: keep the fewest components explaining the fraction F\n"
    "                                   of the variance (default 0.99)\n"
    "            --mean-output FILE.off pca: the mean shape, the model's rest mesh (default\n"
    "                                   FILE.mean.off beside the .U)\n"
    "            --scaling S            polynomial: stiffness (diagonalised against the reduced\n"
    "                                   stiffness, filtered weights; default) or displacement\n"
    "                                   (largest vertex displacement = box diagonal, weights 1)\n"
    "            --input FILE.U         stiffness: the basis to scale\n"
    "            --youngs E --poisson NU --density RHO   material (Pa, -, kg/m^3; default\n"
    "                                   1e6, 0.4, 1100), mesh units are metres\n"
    "            --volume V             auto (TetGen for closed surfaces, else voxels), tetgen,\n"
    "                                   voxel (default auto)\n"
    "            --voxel-resolution N   cells along the longest side (default 40)\n"
    "            --tetgen-max-volume X  largest tetrahedron (mesh units cubed; default none)\n"
    "            --filter-ratio L       weight filter lambda -> (1/lambda + 1/(L lambda_min))^-1\n"
    "                                   (default 100)\n"
    "            --output FILE.U        the basis; weights go to FILE.weights unless\n"
    "            --weights-output FILE  says otherwise\n"
    "  demo      the main job: a scene of modal objects, CCD every step with certificates\n"
    "            (SSCC) and without (traditional), FCL on a few steps, a contact response;\n"
    "            table, plots (the spring: its sound, a WAV at 44.1 kHz), and\n"
    "            the line 'demo: scene=... speedup=X agree=yes|no'. With no options: sixteen\n"
    "            bunnies dropped and struck (basis and certificates computed once, cached)\n"
    "            --scene S              bunnies (default), spring (a double-helix spring) or\n"
    "                                   dragon (../shared's dragon, polynomial modes)\n"
    "            --mesh FILE            another mesh (default data/bunny15k.off; spring: generated)\n"
    "            --basis FILE.U         a modal basis with FILE.weights (default: modal analysis)\n"
    "            --modes R              modes of the modal analysis (default 30; spring 20)\n"
    "            --objects N            instances (default 16; spring 1)\n"
    "            --steps N --dt S       time steps and their length (default 300, 0.01 s;\n"
    "                                   spring 44100, 1/44100 s, traditional on every 50th)\n"
    "            --seed S               the scene's random events (default 1)\n"
    "            --fcl-steps N          steps also run through FCL (default 4; 0: none)\n"
    "            --damping Z            damping ratio of every mode (default 0.1; spring 0.02)\n"
    "            --strike-speed V       m/s of the strikes (default 6; spring 2, up to 1.5 V)\n"
    "            --youngs E --poisson NU --density RHO   material for the modal analysis\n"
    "                                   (default 2e7 Pa, 0.4, 1100 kg/m^3: stiff rubber;\n"
    "                                   spring 2e11, 0.3, 7800: steel)\n"
    "            --cache DIR            basis and certificates (default demo-cache)\n"
    "            --output DIR           plots and CSV (default demo-output)\n"
    "  bench     the benchmarks beside the SSCC paper's Tables 1 and 2: the demo scenes (and the\n"
    "            dragon when ../shared is there), certificate epsilon and kernel tolerance\n"
    "            against time; bench.md, CSV and plots\n"
    "            --steps N              steps per scene (default 300)\n"
    "            --seed S --cache DIR   as for demo\n"
    "            --kernel-queries N     random kernel queries per kind (default 20000)\n"
    "            --output DIR           default bench-output\n"
    "            the self-CCD table: traditional, normal cones, displacement bounds, both, SSCC\n"
    "            (certificates cached in --cache) and FCL on every mesh of\n"
    "            --meshes DIR (default ../shared/data/meshes) at amplitudes 0.01, 0.05, 0.2\n"
    "            --table-steps N        steps per mesh and amplitude (default 3)\n"
    "            --table-repeats R      timed runs of each query per step (each after an untimed\n"
    "                                   one); the median is kept (default 5)\n"
    "            --only self-ccd        run only that table\n"
    "  decimate  quadric edge collapse of a mesh to a triangle count (OpenMesh)\n"
    "            --mesh FILE --triangles N (default 15000) --output FILE.off\n"
    "  selfccd   continuous self-collision over a seeded random trajectory\n"
    "            --mesh FILE            OFF, OBJ or PLY\n"
    "            --basis polynomial:R | FILE.U | FILE   (default polynomial:27)\n"
    "            --weights FILE         weights of the modes (default all 1)\n"
    "            --steps N --amplitude A --seed S   trajectory: ||q||_M stays near A\n"
    "            --burst B              every 100 steps the amplitude swells to B times A\n"
    "                                   and back over 10 steps\n"
    "            --certificates FILE    certificate file from precompute (method sscc)\n"
    "            --methods LIST         comma-separated: sscc (the library's defaults, with the\n"
    "                                   certificates), cones (normal cones only), bounds\n"
    "                                   (displacement bounds only), traditional (no cull of\n"
    "                                   these), exhaustive, fcl\n"
    "  poses     subspace from example poses, end to end: seeded synthetic poses (twist, bend,\n"
    "            polynomial modes), PCA, key points, sound certificates and the EXPERIMENTAL,\n"
    "            NOT CONSERVATIVE regression-predicted culling, false culls side by side\n"
    "            --mesh FILE            OFF, OBJ or PLY\n"
    "            --poses N --held-out H training and held-out poses (default 40, 20)\n"
    "            --seed S               default 1\n"
    "            --twist A --bend B     largest end angles, radians (default 1, 1.5)\n"
    "            --amplitude A          polynomial displacement, box diagonals (default 0.02)\n"
    "            --variance F | --modes R   components kept (default variance 0.999)\n"
    "            --key-radius F         key point sampling radius, box diagonals (default 0.1)\n"
    "            --greedy G             greedy key point additions (default 8)\n"
    "            --epsilon E --global-scale G   certificates, as for precompute (default 0.1, 4)\n"
    "  stress    the whole pipeline (certificates, certified and traditional queries, query_positions,\n"
    "            a scene step) against an independent per-feature brute force under conditions\n"
    "            chosen to break it (far from the origin, 2^-30 to 2^30 scales, ranks 1 to 300,\n"
    "            weights over 12 decades, certificate boundaries, degenerate meshes, 1 to 10^6\n"
    "            triangles), then a long scene run on every thread against one; a table and the\n"
    "            line 'stress: cases=N identical=N refused=N mismatches=N' (non-zero exit on a\n"
    "            mismatch)\n"
    "            --quick                a few small cases and 500 scene steps (seconds)\n"
    "            --seed S               default 1\n"
    "            --load-steps N         steps of the long scene run (default 100000)\n"
    "            --case N               only case N of the table (no long run)\n"
    "  scale     how the pipeline grows with the mesh: the 27 polynomial modes, hierarchy, default\n"
    "            certificates and query steps on one mesh, timed, with the process's peak memory;\n"
    "            the line 'scale: triangles=N ... peak_rss_mb=X' (scripts/scale.sh: a table of sizes)\n"
    "            --triangles N          a geodesic sphere of about N triangles (default 10000)\n"
    "            --mesh FILE            a mesh file instead\n"
    "            --steps N              query steps (default 100)\n"
    "            --amplitude A          the trajectory's ||q||_M in root radii (default 2)\n"
    "            --seed S               the trajectory's (default 1)\n"
    "  help      this text\n";

[[noreturn]] void usage_error(const std::string& message) {
  std::cerr << "sscc: " << message << "\n\n" << kUsage;
  std::exit(2);
}

/// Flags that take no value (besides --quiet).
const std::set<std::string> kSwitches{"--exclude-rest-contacts", "--separation-only"};

/// "--flag value" pairs, "--quiet" and switches, checked against the command's known flags.
struct Flags {
  bool quiet = false;
  std::set<std::string> switches;
  std::map<std::string, std::string> values;

  bool has(const std::string& flag) const { return values.count(flag) != 0; }
  bool on(const std::string& flag) const { return switches.count(flag) != 0; }
  const std::string& text(const std::string& flag) const { return values.at(flag); }

  /// Any finite number.
  double real(const std::string& flag) const {
    const std::string& value = text(flag);
    try {
      std::size_t used = 0;
      const double v = std::stod(value, &used);
      if (used != value.size() || !std::isfinite(v)) throw std::invalid_argument(value);
      return v;
    } catch (const std::exception&) {
      usage_error(flag + " expects a number, got '" + value + "'");
    }
  }

  /// A non-negative number: an integer when Number is integral.
  template <typename Number>
  Number number(const std::string& flag) const {
    const std::string& value = text(flag);
    try {
      std::size_t used = 0;
      const double v =
          std::is_integral<Number>::value ? static_cast<double>(std::stol(value, &used)) : std::stod(value, &used);
      if (used != value.size() || !(v >= 0.0)) throw std::invalid_argument(value);
      return static_cast<Number>(v);
    } catch (const std::exception&) {
      usage_error(flag + " expects a non-negative " + (std::is_integral<Number>::value ? "integer" : "number") +
                  ", got '" + value + "'");
    }
  }
};

Flags parse_flags(const std::vector<std::string>& args, const std::set<std::string>& known,
                  const std::string& command) {
  Flags flags;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& flag = args[i];
    if (flag == "--quiet") {
      flags.quiet = true;
      continue;
    }
    if (known.count(flag) == 0) usage_error("unknown option '" + flag + "' for '" + command + "'");
    if (kSwitches.count(flag) != 0) {
      flags.switches.insert(flag);
      continue;
    }
    if (i + 1 >= args.size()) usage_error(flag + " needs a value");
    flags.values[flag] = args[++i];
  }
  return flags;
}

/// Runs a report with progress on standard error unless quiet; non-zero exit on problems.
template <typename Options, typename Report>
int run_report(const Options& options, bool quiet, Report report, const std::string& command) {
  std::ostream null_stream(nullptr);
  const long problems = report(options, std::cout, quiet ? null_stream : std::cerr);
  if (problems != 0) {
    std::cerr << "sscc " << command << ": " << problems << " disagreements\n";
    return 1;
  }
  return 0;
}

/// "A:B" with A < B.
std::pair<std::uint64_t, std::uint64_t> seed_range(const std::string& text) {
  const std::size_t colon = text.find(':');
  try {
    std::size_t used_begin = 0, used_end = 0;
    const std::uint64_t begin = std::stoull(text.substr(0, colon), &used_begin);
    const std::uint64_t end = std::stoull(text.substr(colon + 1), &used_end);
    if (colon == std::string::npos || used_begin != colon || used_end != text.size() - colon - 1 || begin >= end ||
        text[0] == '-' || text[colon + 1] == '-') {
      throw std::invalid_argument(text);
    }
    return {begin, end};
  } catch (const std::exception&) {
    usage_error("--seeds expects A:B with 0 <= A < B, got '" + text + "'");
  }
}

int run_kernels(const std::vector<std::string>& args) {
  const Flags flags = parse_flags(args,
                                  {"--queries", "--random", "--seed", "--output", "--repeats", "--search-slow",
                                   "--exponent-range", "--separation-only", "--seeds", "--per-seed"},
                                  "kernels");
  if (flags.has("--seeds")) {
    for (const char* other : {"--queries", "--random", "--seed", "--search-slow", "--separation-only"}) {
      if (flags.has(other) || flags.on(other)) usage_error(std::string("kernels --seeds does not take ") + other);
    }
    sscc::validation::SeedRangeOptions range;
    std::tie(range.begin, range.end) = seed_range(flags.text("--seeds"));
    if (flags.has("--per-seed")) range.per_seed = flags.number<long>("--per-seed");
    if (range.per_seed < 1) usage_error("--per-seed must be positive");
    return run_report(range, flags.quiet, sscc::validation::run_seed_range, "kernels");
  }
  if (flags.has("--per-seed")) usage_error("--per-seed goes with --seeds A:B");
  sscc::validation::KernelValidationOptions options;
  if (flags.has("--queries")) options.queries_dir = flags.text("--queries");
  if (flags.has("--random")) options.random = flags.number<long>("--random");
  if (flags.has("--seed")) options.seed = flags.number<std::uint64_t>("--seed");
  if (flags.has("--output")) options.output_dir = flags.text("--output");
  if (flags.has("--repeats")) options.repeats = flags.number<int>("--repeats");
  if (flags.has("--search-slow")) options.search_slow = flags.number<long>("--search-slow");
  if (flags.has("--exponent-range")) options.exponent_range = flags.number<int>("--exponent-range");
  options.separation_only = flags.on("--separation-only");
  if (options.separation_only && (options.random == 0 || !options.queries_dir.empty() || options.search_slow != 0)) {
    usage_error("kernels --separation-only needs --random N and neither --queries nor --search-slow");
  }
  if (options.queries_dir.empty() && options.random == 0 && options.search_slow == 0) {
    usage_error("kernels needs --queries DIR, --random N or --search-slow N");
  }
  return run_report(options, flags.quiet, sscc::validation::run_kernel_validation, "kernels");
}

std::vector<std::string> split_list(const std::string& list) {
  std::vector<std::string> items;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

sscc::validation::ModelSource model_source(const Flags& flags) {
  sscc::validation::ModelSource source;
  source.mesh = flags.text("--mesh");
  if (flags.has("--basis")) source.basis = flags.text("--basis");
  if (flags.has("--weights")) source.weights = flags.text("--weights");
  source.exclude_rest_contacts = flags.on("--exclude-rest-contacts");
  return source;
}

/// "I/N" with 0 <= I < N.
std::pair<int, int> shard_of(const std::string& text) {
  const std::size_t slash = text.find('/');
  try {
    std::size_t used_index = 0, used_count = 0;
    const int index = std::stoi(text.substr(0, slash), &used_index);
    const int count = std::stoi(text.substr(slash + 1), &used_count);
    if (slash == std::string::npos || used_index != slash || used_count != text.size() - slash - 1 || index < 0 ||
        index >= count) {
      throw std::invalid_argument(text);
    }
    return {index, count};
  } catch (const std::exception&) {
    usage_error("--shard expects I/N with 0 <= I < N, got '" + text + "'");
  }
}

int run_precompute(const std::vector<std::string>& args) {
  const Flags flags = parse_flags(args,
                                  {"--mesh", "--basis", "--weights", "--epsilon", "--global-scale", "--output",
                                   "--exclude-rest-contacts", "--shard"},
                                  "precompute");
  if (!flags.has("--mesh")) usage_error("precompute needs --mesh FILE");
  if (!flags.has("--output")) usage_error("precompute needs --output FILE.sscc");
  sscc::validation::PrecomputeCommandOptions options;
  options.model = model_source(flags);
  options.output = flags.text("--output");
  if (flags.has("--epsilon")) options.parameters.epsilon = flags.number<double>("--epsilon");
  if (flags.has("--global-scale")) options.parameters.global_radius_scale = flags.number<double>("--global-scale");
  if (flags.has("--shard")) std::tie(options.shard_index, options.shard_count) = shard_of(flags.text("--shard"));
  return run_report(options, flags.quiet, sscc::validation::run_precompute, "precompute");
}

int run_merge(const std::vector<std::string>& args) {
  // The shard files are the arguments that are neither a flag nor a flag's value.
  std::vector<std::string> flag_args;
  sscc::validation::MergeCommandOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i].rfind("--", 0) != 0) {
      options.shards.push_back(args[i]);
      continue;
    }
    flag_args.push_back(args[i]);
    if (args[i] != "--quiet" && kSwitches.count(args[i]) == 0 && i + 1 < args.size()) flag_args.push_back(args[++i]);
  }
  const Flags flags =
      parse_flags(flag_args, {"--mesh", "--basis", "--weights", "--output", "--exclude-rest-contacts"}, "merge");
  if (!flags.has("--mesh")) usage_error("merge needs --mesh FILE");
  if (!flags.has("--output")) usage_error("merge needs --output FILE.sscc");
  if (options.shards.empty()) usage_error("merge needs the shard files");
  options.model = model_source(flags);
  options.output = flags.text("--output");
  return run_report(options, flags.quiet, sscc::validation::run_merge, "merge");
}

std::vector<double> number_list(const std::string& flag, const std::string& list) {
  std::vector<double> numbers;
  for (const std::string& item : split_list(list)) {
    try {
      std::size_t used = 0;
      const double v = std::stod(item, &used);
      if (used != item.size() || !(v > 0.0 && v < 1.0)) throw std::invalid_argument(item);
      numbers.push_back(v);
    } catch (const std::exception&) {
      usage_error(flag + " expects numbers in (0, 1), got '" + item + "'");
    }
  }
  return numbers;
}

int run_certificate_sweep(const std::vector<std::string>& args) {
  const Flags flags = parse_flags(
      args, {"--mesh", "--basis", "--weights", "--epsilons", "--steps", "--amplitude", "--burst", "--seed", "--output"},
      "certificates");
  if (!flags.has("--mesh")) usage_error("certificates needs --mesh FILE");
  sscc::validation::CertificateSweepOptions options;
  options.model = model_source(flags);
  if (flags.has("--epsilons")) options.epsilons = number_list("--epsilons", flags.text("--epsilons"));
  if (flags.has("--steps")) options.steps = flags.number<int>("--steps");
  if (flags.has("--amplitude")) options.amplitude = flags.number<double>("--amplitude");
  if (flags.has("--burst")) options.burst = flags.number<double>("--burst");
  if (flags.has("--seed")) options.seed = flags.number<std::uint64_t>("--seed");
  if (flags.has("--output")) options.output_dir = flags.text("--output");
  if (options.steps <= 0) usage_error("--steps must be positive");
  if (options.epsilons.empty()) usage_error("--epsilons needs at least one value");
  return run_report(options, flags.quiet, sscc::validation::run_certificate_sweep, "certificates");
}

/// --modes R or --variance F (not both) for a PCA.
void pca_options(const Flags& flags, sscc::PcaOptions& pca) {
  if (flags.has("--modes") && flags.has("--variance")) usage_error("give --modes or --variance, not both");
  if (flags.has("--modes")) pca.modes = flags.number<int>("--modes");
  if (flags.has("--variance")) pca.variance_fraction = flags.number<double>("--variance");
}

int run_basis(const std::vector<std::string>& args) {
  const Flags flags =
      parse_flags(args,
                  {"--mesh", "--method", "--modes", "--scaling", "--input", "--youngs", "--poisson", "--density",
                   "--volume", "--voxel-resolution", "--tetgen-max-volume", "--filter-ratio", "--output",
                   "--weights-output", "--poses", "--variance", "--mean-output"},
                  "basis");
  if (!flags.has("--mesh")) usage_error("basis needs --mesh FILE");
  if (!flags.has("--output")) usage_error("basis needs --output FILE.U");
  sscc::validation::BasisCommandOptions options;
  options.mesh = flags.text("--mesh");
  options.output = flags.text("--output");
  if (flags.has("--weights-output")) options.weights_output = flags.text("--weights-output");
  if (flags.has("--method")) options.method = flags.text("--method");
  if (flags.has("--modes")) options.elastic.modes = flags.number<int>("--modes");
  if (flags.has("--poses")) options.poses = split_list(flags.text("--poses"));
  if (flags.has("--mean-output")) options.mean_output = flags.text("--mean-output");
  if (options.method == "pca") pca_options(flags, options.pca);
  if (flags.has("--scaling")) {
    const std::string& scaling = flags.text("--scaling");
    if (scaling == "stiffness") {
      options.scaling = sscc::validation::PolynomialScaling::kStiffness;
    } else if (scaling == "displacement") {
      options.scaling = sscc::validation::PolynomialScaling::kDisplacement;
    } else {
      usage_error("--scaling expects stiffness or displacement, got '" + scaling + "'");
    }
  }
  if (flags.has("--input")) options.input_basis = flags.text("--input");
  if (flags.has("--youngs")) options.elastic.material.youngs_modulus = flags.real("--youngs");
  if (flags.has("--poisson")) options.elastic.material.poisson_ratio = flags.real("--poisson");
  if (flags.has("--density")) options.elastic.material.density = flags.real("--density");
  if (flags.has("--volume")) options.elastic.volume.method = sscc::parse_volume_method(flags.text("--volume"));
  if (flags.has("--voxel-resolution"))
    options.elastic.volume.voxel_resolution = flags.number<int>("--voxel-resolution");
  if (flags.has("--tetgen-max-volume")) {
    options.elastic.volume.tetgen_max_volume = flags.number<double>("--tetgen-max-volume");
  }
  if (flags.has("--filter-ratio")) options.elastic.weight_filter_ratio = flags.number<double>("--filter-ratio");
  return run_report(options, flags.quiet, sscc::validation::run_basis, "basis");
}

/// The scene flags shared by demo and bench.
const std::set<std::string> kSceneFlags{"--scene",
                                        "--mesh",
                                        "--basis",
                                        "--modes",
                                        "--objects",
                                        "--steps",
                                        "--dt",
                                        "--seed",
                                        "--fcl-steps",
                                        "--damping",
                                        "--youngs",
                                        "--poisson",
                                        "--density",
                                        "--cache",
                                        "--strike-speed",
                                        "--scale",
                                        "--exclude-rest-contacts"};

void scene_run_options(const Flags& flags, sscc::validation::SceneRunOptions& o) {
  if (flags.has("--scene")) o.scene = flags.text("--scene");
  if (flags.has("--mesh")) o.mesh = flags.text("--mesh");
  if (flags.has("--basis")) o.basis = flags.text("--basis");
  if (flags.has("--modes")) o.modes = flags.number<int>("--modes");
  if (flags.has("--objects")) o.objects = flags.number<int>("--objects");
  if (flags.has("--steps")) o.steps = flags.number<int>("--steps");
  if (flags.has("--dt")) o.dt = flags.number<double>("--dt");
  if (flags.has("--seed")) o.seed = flags.number<std::uint64_t>("--seed");
  if (flags.has("--fcl-steps")) o.fcl_steps = flags.number<int>("--fcl-steps");
  if (flags.has("--damping")) o.damping_ratio = flags.number<double>("--damping");
  if (flags.has("--youngs")) o.youngs_modulus = flags.real("--youngs");
  if (flags.has("--poisson")) o.poisson_ratio = flags.real("--poisson");
  if (flags.has("--density")) o.density = flags.real("--density");
  if (flags.has("--cache")) o.cache_dir = flags.text("--cache");
  if (flags.has("--strike-speed")) o.strike_speed = flags.real("--strike-speed");
  if (flags.has("--scale")) o.scale = flags.text("--scale");
  o.exclude_rest_contacts = flags.on("--exclude-rest-contacts");
}

std::set<std::string> with_flags(std::set<std::string> flags, std::initializer_list<std::string> more) {
  flags.insert(more);
  return flags;
}

bool wants_help(const std::vector<std::string>& args) {
  return std::find(args.begin(), args.end(), "--help") != args.end() ||
         std::find(args.begin(), args.end(), "-h") != args.end();
}

int run_demo(const std::vector<std::string>& args) {
  if (wants_help(args)) {
    std::cout << kUsage;
    return 0;
  }
  const Flags flags = parse_flags(args, with_flags(kSceneFlags, {"--output"}), "demo");
  sscc::validation::DemoOptions options;
  scene_run_options(flags, options.run);
  if (flags.has("--output")) options.output_dir = flags.text("--output");
  return run_report(options, flags.quiet, sscc::validation::run_demo, "demo");
}

int run_bench(const std::vector<std::string>& args) {
  const Flags flags = parse_flags(args,
                                  {"--steps", "--seed", "--cache", "--kernel-queries", "--output", "--meshes",
                                   "--table-steps", "--table-repeats", "--only"},
                                  "bench");
  sscc::validation::BenchOptions options;
  if (flags.has("--steps")) options.steps = flags.number<int>("--steps");
  if (flags.has("--seed")) options.seed = flags.number<std::uint64_t>("--seed");
  if (flags.has("--cache")) options.cache_dir = flags.text("--cache");
  if (flags.has("--kernel-queries")) options.kernel_queries = flags.number<long>("--kernel-queries");
  if (flags.has("--output")) options.output_dir = flags.text("--output");
  if (flags.has("--meshes")) options.meshes_dir = flags.text("--meshes");
  if (flags.has("--table-steps")) options.table_steps = flags.number<int>("--table-steps");
  if (flags.has("--table-repeats")) options.table_repeats = flags.number<int>("--table-repeats");
  if (options.table_steps <= 0) usage_error("--table-steps must be positive");
  if (options.table_repeats <= 0) usage_error("--table-repeats must be positive");
  if (flags.has("--only")) {
    if (flags.text("--only") != "self-ccd") usage_error("--only takes self-ccd");
    options.self_ccd_table_only = true;
  }
  return run_report(options, flags.quiet, sscc::validation::run_bench, "bench");
}

int run_decimate(const std::vector<std::string>& args) {
  const Flags flags = parse_flags(args, {"--mesh", "--triangles", "--output"}, "decimate");
  if (!flags.has("--mesh")) usage_error("decimate needs --mesh FILE");
  if (!flags.has("--output")) usage_error("decimate needs --output FILE");
  sscc::validation::DecimateCommandOptions options;
  options.mesh = flags.text("--mesh");
  options.output = flags.text("--output");
  if (flags.has("--triangles")) options.triangles = flags.number<int>("--triangles");
  return run_report(options, flags.quiet, sscc::validation::run_decimate, "decimate");
}

int run_poses(const std::vector<std::string>& args) {
  const Flags flags = parse_flags(args,
                                  {"--mesh", "--poses", "--held-out", "--seed", "--twist", "--bend", "--amplitude",
                                   "--variance", "--modes", "--key-radius", "--greedy", "--epsilon", "--global-scale"},
                                  "poses");
  if (!flags.has("--mesh")) usage_error("poses needs --mesh FILE");
  sscc::validation::PosesCommandOptions options;
  options.mesh = flags.text("--mesh");
  if (flags.has("--poses")) options.training = flags.number<int>("--poses");
  if (flags.has("--held-out")) options.held_out = flags.number<int>("--held-out");
  if (flags.has("--seed")) options.generator.seed = flags.number<std::uint64_t>("--seed");
  if (flags.has("--twist")) options.generator.twist = flags.number<double>("--twist");
  if (flags.has("--bend")) options.generator.bend = flags.number<double>("--bend");
  if (flags.has("--amplitude")) options.generator.modal_amplitude = flags.number<double>("--amplitude");
  pca_options(flags, options.pca);
  if (flags.has("--key-radius")) options.key_points.radius_fraction = flags.number<double>("--key-radius");
  if (flags.has("--greedy")) options.key_points.greedy_additions = flags.number<int>("--greedy");
  if (flags.has("--epsilon")) options.certificates.epsilon = flags.number<double>("--epsilon");
  if (flags.has("--global-scale")) options.certificates.global_radius_scale = flags.number<double>("--global-scale");
  if (options.training < 2 || options.held_out < 1) usage_error("poses needs --poses >= 2 and --held-out >= 1");
  return run_report(options, flags.quiet, sscc::validation::run_poses, "poses");
}

int run_stress(std::vector<std::string> args) {
  sscc::validation::StressOptions options;
  const auto quick = std::find(args.begin(), args.end(), "--quick");
  if (quick != args.end()) {
    options.quick = true;
    args.erase(quick);
  }
  const Flags flags = parse_flags(args, {"--seed", "--load-steps", "--case"}, "stress");
  if (flags.has("--case")) options.only_case = flags.number<long>("--case");
  if (flags.has("--seed")) options.seed = flags.number<std::uint64_t>("--seed");
  if (flags.has("--load-steps")) options.load_steps = flags.number<long>("--load-steps");
  return run_report(options, flags.quiet, sscc::validation::run_stress, "stress");
}

int run_scale(const std::vector<std::string>& args) {
  const Flags flags = parse_flags(args, {"--triangles", "--mesh", "--steps", "--amplitude", "--seed"}, "scale");
  sscc::validation::ScaleOptions options;
  if (flags.has("--triangles")) options.triangles = flags.number<long>("--triangles");
  if (flags.has("--mesh")) options.mesh = flags.text("--mesh");
  if (flags.has("--steps")) options.steps = flags.number<int>("--steps");
  if (flags.has("--amplitude")) options.amplitude = flags.number<double>("--amplitude");
  if (flags.has("--seed")) options.seed = flags.number<std::uint64_t>("--seed");
  if (options.steps <= 0) usage_error("--steps must be positive");
  return run_report(options, flags.quiet, sscc::validation::run_scale, "scale");
}

int run_selfccd(const std::vector<std::string>& args) {
  const Flags flags = parse_flags(args,
                                  {"--mesh", "--basis", "--weights", "--steps", "--amplitude", "--burst", "--seed",
                                   "--methods", "--certificates", "--exclude-rest-contacts"},
                                  "selfccd");
  sscc::validation::SelfCcdValidationOptions options;
  if (!flags.has("--mesh")) usage_error("selfccd needs --mesh FILE");
  options.model = model_source(flags);
  if (flags.has("--steps")) options.steps = flags.number<int>("--steps");
  if (flags.has("--amplitude")) options.amplitude = flags.number<double>("--amplitude");
  if (flags.has("--burst")) options.burst = flags.number<double>("--burst");
  if (flags.has("--certificates")) options.certificates = flags.text("--certificates");
  if (flags.has("--seed")) options.seed = flags.number<std::uint64_t>("--seed");
  if (flags.has("--methods")) options.methods = split_list(flags.text("--methods"));
  if (options.steps <= 0) usage_error("--steps must be positive");
  if (options.methods.empty()) usage_error("--methods needs at least one method");
  for (std::size_t i = 0; i < options.methods.size(); ++i) {
    // Each method's figures are kept once: a repeat would add its times to the first run's.
    if (std::find(options.methods.begin(), options.methods.begin() + i, options.methods[i]) !=
        options.methods.begin() + i) {
      usage_error("--methods lists '" + options.methods[i] + "' twice");
    }
  }
  return run_report(options, flags.quiet, sscc::validation::run_selfccd_validation, "selfccd");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) usage_error("no command given");
  const std::string command = argv[1];
  std::vector<std::string> args;
  for (int i = 2; i < argc; ++i) {  // --threads N, for every command
    if (std::string(argv[i]) != "--threads") {
      args.emplace_back(argv[i]);
      continue;
    }
    if (i + 1 >= argc) usage_error("--threads needs a value");
    const std::string value = argv[++i];
    char* end = nullptr;
    const long threads = std::strtol(value.c_str(), &end, 10);
    if (value.empty() || *end != '\0' || threads < 1 || threads > 4096) {
      usage_error("--threads expects a positive integer, got '" + value + "'");
    }
    sscc::set_default_threads(static_cast<int>(threads));
  }
  try {
    if (command == "kernels") return run_kernels(args);
    if (command == "selfccd") return run_selfccd(args);
    if (command == "precompute") return run_precompute(args);
    if (command == "merge") return run_merge(args);
    if (command == "certificates") return run_certificate_sweep(args);
    if (command == "basis") return run_basis(args);
    if (command == "decimate") return run_decimate(args);
    if (command == "demo") return run_demo(args);
    if (command == "bench") return run_bench(args);
    if (command == "poses") return run_poses(args);
    if (command == "stress") return run_stress(args);
    if (command == "scale") return run_scale(args);
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
