// A computation that may crash instead of reporting (TetGen on some invalid inputs), run in
// a forked child process so that a crash there becomes an exception in the caller instead
// of taking it down. Private to the library.
#pragma once

#include <functional>
#include <string>

namespace sscc::detail {

/// Runs `work` in a child process and returns the bytes it returned. Throws
/// std::runtime_error: with the message of the exception `work` threw; "<what> crashed
/// (signal N)" when the child died of a signal; "<what> failed without a result" when it
/// ended in any other way without handing back a whole answer; or when it cannot start.
std::string run_in_child(const std::string& what, const std::function<std::string()>& work);

}  // namespace sscc::detail
