// Any bytes as a Vega .U basis: a finite matrix of the stated size or a std::runtime_error
// naming the problem, never a crash.
#include <cstdlib>
#include <stdexcept>

#include "fuzz_support.hpp"
#include "sscc/model/basis_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = sscc::fuzz::scratch_file(data, size, ".U");
  try {
    const Eigen::MatrixXd basis = sscc::read_basis(path);
    if (!basis.allFinite() || basis.size() == 0) std::abort();
  } catch (const std::runtime_error&) {
  }
  return 0;
}
