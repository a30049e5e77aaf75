#!/usr/bin/env bash
# scripts/fuzz.sh SECONDS [FORMAT...]: runs each libFuzzer target of tests/io/fuzz/ (all, or the
# formats named: tsurf model3d obj medit medit_volume vtu vtu_volume gmsh gmsh_volume tetgen)
# for SECONDS under ASan+UBSan, and prints executions and findings per target.
#
# Build: clang in $VOROSEAL_FUZZ_BUILD (default build-fuzz/), with ccache when present.
# Corpus: the committed seeds tests/io/fuzz/corpus/<format>/ are read; what the fuzzer finds
# goes to $VOROSEAL_FUZZ_WORK/<format>/ (default tests/io/fuzz/corpus/work/, not committed), kept
# from run to run. Crashing inputs go to $VOROSEAL_FUZZ_BUILD/artifacts/.
# Exit: 0 when no target found anything, 1 otherwise, 77 when clang is not installed.
set -euo pipefail

if [ $# -lt 1 ] || ! [[ "$1" =~ ^[0-9]+$ ]]; then
  echo "usage: scripts/fuzz.sh SECONDS [FORMAT...]" >&2
  exit 2
fi
seconds=$1
shift
root=$(cd "$(dirname "$0")/.." && pwd)
build=${VOROSEAL_FUZZ_BUILD:-$root/build-fuzz}
work=${VOROSEAL_FUZZ_WORK:-$root/tests/io/fuzz/corpus/work}
seeds=$root/tests/io/fuzz/corpus
formats=("$@")
[ ${#formats[@]} -gt 0 ] || formats=(tsurf model3d obj medit medit_volume vtu vtu_volume gmsh gmsh_volume tetgen)

clangxx=$(command -v clang++ || true)
clangc=$(command -v clang || true)
if [ -z "$clangxx" ] || [ -z "$clangc" ]; then
  echo "fuzz: clang not installed: skipped"
  exit 77
fi

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$root}
sanitize="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fsanitize=fuzzer-no-link"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER="$clangc" -DCMAKE_CXX_COMPILER="$clangxx" "${launcher[@]}" \
    -DCMAKE_CXX_FLAGS="$sanitize" -DVOROSEAL_BUILD_FUZZERS=ON -DVOROSEAL_BUILD_BENCH=OFF >/dev/null
fi
targets=()
for f in "${formats[@]}"; do targets+=(--target "fuzz_$f"); done
nice cmake --build "$build" -j2 "${targets[@]}" >/dev/null

# The seed directory of each target (two targets read the same files as surfaces or tets).
seed_dir() {
  case $1 in
    tsurf) echo ts ;; model3d) echo ml ;; obj) echo obj ;; medit | medit_volume) echo mesh ;;
    vtu | vtu_volume) echo vtu ;; gmsh | gmsh_volume) echo msh ;; tetgen) echo tetgen ;;
  esac
}

mkdir -p "$build/artifacts"
failed=0
printf "%-14s %12s %10s  %s\n" target executions "exec/s" result
for f in "${formats[@]}"; do
  mkdir -p "$work/$f"
  log="$build/artifacts/fuzz_$f.log"
  status=0
  # UBSan reports abort (halt_on_error) so that libFuzzer records them as crashes.
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1 \
    nice "$build/tests/io/fuzz/fuzz_$f" -max_total_time="$seconds" -max_len=8192 -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build/artifacts/fuzz_$f-" \
    "$work/$f" "$seeds/$(seed_dir "$f")" >"$log" 2>&1 || status=$?
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  if [ $status -eq 0 ]; then
    result=ok
  else
    result="FOUND SOMETHING (exit $status; see $log)"
    failed=1
  fi
  printf "%-14s %12s %10s  %s\n" "fuzz_$f" "${runs:-0}" "${rate:-0}" "$result"
done
exit $failed
