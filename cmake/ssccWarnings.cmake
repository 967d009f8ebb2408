# The project's warning flags, set in one place. SSCC_WARNINGS_AS_ERRORS (on in CI) turns
# them into errors.
option(SSCC_WARNINGS_AS_ERRORS "Treat compiler warnings as errors" OFF)

function(sscc_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
  if(SSCC_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
