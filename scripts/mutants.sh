#!/usr/bin/env bash
# Mutation testing: is the test suite strong enough to notice a broken guarantee?
#
# Each mutant is a compile definition, SSCC_MUTANT_<NAME>, that breaks one guarantee at one
# spot of the library (grep -rn SSCC_MUTANT_ src ccd_kernels include); normal builds never
# define one, so the hooks compile to nothing. Each is built into build-mutant-<name>/ (the
# test target only) and run against the tests that guard its guarantee. The definition is
# given only to the files that hold or include the hook (CMake's SSCC_MUTANT_SOURCES), and
# the build directories sit beside build/, at its depth (ccache, with base_dir = /work,
# hashes paths relative to the build directory): every other file comes from ccache. A mutant is KILLED when those tests fail,
# SURVIVED when they pass. The same tests must first pass on an unmutated build.
#
#   bash scripts/mutants.sh            # every mutant
#   bash scripts/mutants.sh NAME...    # some (names without the SSCC_MUTANT_ prefix)
#
# Exits 1 when a mutant survives (or a build fails), 2 when the unmutated build fails.
set -euo pipefail
cd "$(dirname "$0")/.."

# Mutant -> the Catch2 test spec that must notice it.
declare -A guard=(
  [OWNS_ALWAYS_TRUE]='[brute_force]'               # each feature pair tested once (self_ccd.cpp)
  [NO_SHIFT_MARGIN]='[moving_frame]'               # moving-frame rounding pad (moving_frame.hpp)
  [SEPARATION_3D]='[separation]'                   # minimum separation searched at d (kernels.cpp)
  [INFLATE_RADII]='[tightness]'                    # radii but the root's x1.1 (precompute.cpp)
  [NO_CONSTANT_MODE_MULTIPLIER]='[bounds]'         # pair bound >= perturbation bound (triangle_pair_bound.cpp)
  [BOX_BOX_SINGLE_MODE]='[bounds]'                 # box-box bound in 2-norm, not per mode (box_box_bound.cpp)
  [ACCEPT_REFLECTIONS]='[frames]'                  # frames with det < 0 refused (scene.cpp)
  [NO_POSITION_ROUNDING]='[rounding]'              # certificates pad position rounding (triangle_pair_bound.cpp)
  [GRAM_PAD_FIXED]='[rounding]'                    # Gram pad grows with r (triangle_pair_bound.hpp)
  [DISPLACEMENT_NO_CENTRES]='[displacement]'       # two nodes' relative motion counted (displacement_bound.cpp)
  [AFFINE_NO_RESIDUAL]='[displacement]'            # what the affine fit leaves out counted (displacement_bound.cpp)
  [PLANE_NO_BOUND]='[separating_plane]'            # the separating planes' rounding bound (separating_plane.hpp)
  [SWEEP_EITHER_END]='[sweep]'                     # apart at both ends of the step, not either (sweep.hpp)
  [CONTOUR_ANY_WINDING]='[contour]'                # the star-shaped contour winds exactly once (contour.cpp)
  [CONTOUR_CROSSING_AT_START]='[contour]'          # contour edges apart at the step's start (simple_contour.cpp)
  [INFLATE_PAIR_RADII]='[tightness]'               # pair certificates x1.5 (precompute.cpp)
  [FLOOR_WITHOUT_SPREAD]='[floor]'                 # the 1D floor counts vertices' own motion (triangle_pair_bound.cpp)
  [QUICK_FLOOR_WITHOUT_SPREAD]='[floor]'           # so does the quick floor (triangle_pair_bound.cpp)
  [PROJECTED_FLOOR_UNPADDED]='[floor]'             # the projected floor covers the bound's slacks (triangle_pair_bound.cpp)
  [PROJECTED_FLOOR_NO_GROWTH]='[floor]'            # the projected floor's growth covers its float sums (triangle_pair_bound.cpp)
  [GROUP_FLOOR_NO_REACH]='[group_floor]'           # the group floor counts vertices' distance from centroids (triangle_pair_bound.cpp)
  [GROUP_FLOOR_NO_DEVIATION]='[group_floor]'       # and the vertex blocks' from the group's (triangle_pair_bound.cpp)
)
order=(OWNS_ALWAYS_TRUE NO_SHIFT_MARGIN SEPARATION_3D INFLATE_RADII NO_CONSTANT_MODE_MULTIPLIER BOX_BOX_SINGLE_MODE
  ACCEPT_REFLECTIONS NO_POSITION_ROUNDING GRAM_PAD_FIXED DISPLACEMENT_NO_CENTRES
  AFFINE_NO_RESIDUAL PLANE_NO_BOUND SWEEP_EITHER_END CONTOUR_ANY_WINDING CONTOUR_CROSSING_AT_START INFLATE_PAIR_RADII
  FLOOR_WITHOUT_SPREAD QUICK_FLOOR_WITHOUT_SPREAD PROJECTED_FLOOR_UNPADDED PROJECTED_FLOOR_NO_GROWTH
  GROUP_FLOOR_NO_REACH GROUP_FLOOR_NO_DEVIATION)
if [ $# -gt 0 ]; then order=("$@"); fi
for name in "${order[@]}"; do
  if [ -z "${guard[$name]+set}" ]; then echo "mutants: unknown mutant $name" >&2; exit 2; fi
  if ! grep -rq "SSCC_MUTANT_$name\b" src ccd_kernels include; then
    echo "mutants: SSCC_MUTANT_$name has no hook in the library" >&2; exit 2
  fi
done

# The translation units that hold a mutant's hook or include the file that does, read from
# the dependency files of the unmutated build (paths there are absolute, or, when ccache has a
# base_dir, relative to the directory the compiler ran in, the one above CMakeFiles/).
units_of() {
  local hooks depfile hook source
  mapfile -t hooks < <(grep -rl "SSCC_MUTANT_$1\b" src ccd_kernels include)
  find build-mutant-unmutated -name '*.o.d' | while read -r depfile; do
    for hook in "${hooks[@]}"; do
      if grep -q "/$(basename "$hook")\b" "$depfile"; then
        # The source is the first name after "target:" (on the first or the second line):
        # relative (ccache with a base_dir rewrites paths so) or absolute.
        source=$(head -2 "$depfile" | tr -d '\\' | tr '\n' ' ' | awk '{print $2}')
        case "$source" in
          /*) realpath "$source" ;;
          *) realpath "${depfile%%/CMakeFiles/*}/$source" ;;
        esac
        break
      fi
    done
  done | sort -u | paste -sd ';'
}

# Builds the test target into build-mutant-<dir>/ (log: build.log there), with mutant
# <name>'s definition in the files that see its hook ("" for none).
build() {
  local dir=build-mutant-$1 name=$2 sources=""
  if [ -n "$name" ]; then sources=$(units_of "$name"); fi
  mkdir -p "$dir"
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_FLAGS="" \
    -DSSCC_MUTANT="$name" \
    -DSSCC_MUTANT_SOURCES="$sources" >"$dir/build.log" 2>&1 &&
    cmake --build "$dir" -j2 --target sscc_tests >>"$dir/build.log" 2>&1
}

# Runs a spec; 0 when its tests pass. A run that does not end in 10 minutes counts as failing.
run() { timeout 600 "build-mutant-$1/bin/sscc_tests" "$2" >"build-mutant-$1/tests.log" 2>&1; }

start=$SECONDS
mapfile -t specs < <(for name in "${order[@]}"; do echo "${guard[$name]}"; done | sort -u)
if ! build unmutated ""; then echo "mutants: the unmutated build failed (build-mutant-unmutated/build.log)" >&2; exit 2; fi
for spec in "${specs[@]}"; do
  if ! run unmutated "$spec"; then
    echo "mutants: $spec fails without a mutant (build-mutant-unmutated/tests.log)" >&2
    exit 2
  fi
done

printf '%-30s %-22s %-9s %s\n' mutant tests result seconds
survived=0
for name in "${order[@]}"; do
  begin=$SECONDS
  dir=$(echo "$name" | tr 'A-Z_' 'a-z-')
  if ! build "$dir" "$name"; then
    result="BUILD-FAILED"
    survived=$((survived + 1))
  elif run "$dir" "${guard[$name]}"; then
    result="SURVIVED"
    survived=$((survived + 1))
  else
    result="KILLED"
  fi
  printf '%-30s %-22s %-9s %d\n' "$name" "${guard[$name]}" "$result" $((SECONDS - begin))
done
echo "mutants: ${#order[@]} run, $survived survived or failed to build, $((SECONDS - start)) s"
[ "$survived" -eq 0 ]
