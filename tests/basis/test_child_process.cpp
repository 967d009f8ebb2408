// The child process TetGen runs in (src/basis/child_process.hpp): a crash there is an error
// in the caller, not a crash of the caller. Checked with computations that die on purpose,
// since no input is known that still crashes TetGen behind the surface checks.
#include <catch2/catch.hpp>

#include <csignal>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "basis/child_process.hpp"

using sscc::detail::run_in_child;

TEST_CASE("child process: results and errors come back, crashes become errors", "[basis][child]") {
  const std::string bytes("bytes\0 with a zero", 18);
  CHECK(run_in_child("echo", [&] { return bytes; }) == bytes);
  const std::string large(3 << 20, 'x');  // more than a pipe holds at once
  CHECK(run_in_child("large", [&] { return large; }) == large);
  CHECK_THROWS_WITH(run_in_child("thrower", []() -> std::string { throw std::runtime_error("told so"); }), "told so");
  CHECK_THROWS_WITH(run_in_child("TetGen",
                                 []() -> std::string {
                                   std::raise(SIGKILL);
                                   return "";
                                 }),
                    Catch::Contains("TetGen crashed (signal 9)"));
  CHECK_THROWS_WITH(run_in_child("TetGen", []() -> std::string { std::abort(); }),
                    Catch::Contains("TetGen crashed (signal " + std::to_string(SIGABRT) + ")"));
  CHECK_THROWS_WITH(run_in_child("quitter", []() -> std::string { std::_Exit(0); }),
                    Catch::Contains("quitter failed without a result"));
  // The caller is still here, and can run more.
  CHECK(run_in_child("again", [] { return std::string("ok"); }) == "ok");
}
