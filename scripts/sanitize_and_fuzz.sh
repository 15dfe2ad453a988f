#!/usr/bin/env bash
# Sanitized build (Clang 14, AddressSanitizer + UndefinedBehaviorSanitizer) in
# build-asan, the ctest suite under it (without label heavy), then every libFuzzer target of
# fuzz/ for a fixed time on a copy of its seed corpus. Exits nonzero on a build
# failure, a failing test, or any fuzzer finding (crash, leak, timeout, OOM).
# docs/fuzzing.md describes the targets and the findings.
#
# Usage: scripts/sanitize_and_fuzz.sh [--no-ctest] [--no-fuzz] [--seconds N] [--targets "a b"]
#
# Environment (each also settable by the flag next to it):
#   FUZZ_SECONDS=60          seconds per fuzz target        (--seconds N)
#   SKIP_CTEST=1             skip the sanitized ctest run   (--no-ctest)
#   SKIP_FUZZ=1              skip the fuzz targets          (--no-fuzz)
#   FUZZ_TARGETS="..."       which targets (default: all)   (--targets "...")
#   BUILD_JOBS=2             cmake --build -j
#   CTEST_JOBS=2             ctest -j
#   FUZZ_TIMEOUT=10          libFuzzer -timeout per input (s)
#   FUZZ_RSS_LIMIT_MB=2048   libFuzzer -rss_limit_mb
#   FUZZ_OUT=build-asan/fuzz-runs   corpora, logs and findings
#   FUZZ_BAD_INPUT_SEEDS=0   1: also seed from tests/bad_input/cases
#   FUZZ_REPLAY_MAX=50       findings replayed to group them by kind
#   SINEW_ASAN_CMAKE_ARGS="" extra arguments for the configure step
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"

FUZZ_SECONDS="${FUZZ_SECONDS:-60}"
SKIP_CTEST="${SKIP_CTEST:-0}"
SKIP_FUZZ="${SKIP_FUZZ:-0}"
BUILD_JOBS="${BUILD_JOBS:-2}"
CTEST_JOBS="${CTEST_JOBS:-2}"
FUZZ_TIMEOUT="${FUZZ_TIMEOUT:-10}"
FUZZ_RSS_LIMIT_MB="${FUZZ_RSS_LIMIT_MB:-2048}"
all_targets="fuzz_tetgen fuzz_gmsh2 fuzz_gmsh4 fuzz_obj fuzz_scene"
FUZZ_TARGETS="${FUZZ_TARGETS:-$all_targets}"
build="build-asan"
FUZZ_OUT="${FUZZ_OUT:-$build/fuzz-runs}"

while [ $# -gt 0 ]; do
  case "$1" in
    --no-ctest) SKIP_CTEST=1 ;;
    --no-fuzz) SKIP_FUZZ=1 ;;
    --seconds) FUZZ_SECONDS="$2"; shift ;;
    --seconds=*) FUZZ_SECONDS="${1#*=}" ;;
    --targets) FUZZ_TARGETS="$2"; shift ;;
    --targets=*) FUZZ_TARGETS="${1#*=}" ;;
    -h|--help) sed -n '2,22p' "$repo/scripts/sanitize_and_fuzz.sh"; exit 0 ;;
    *) echo "sanitize_and_fuzz: unknown argument '$1' (--help)" >&2; exit 2 ;;
  esac
  shift
done

# --- packages: the project's, then the Clang toolchain when missing ----------
bash scripts/setup.sh
packages=(clang-14 libclang-rt-14-dev libomp-14-dev llvm-14)  # libomp: OpenMP with Clang; llvm-14: llvm-symbolizer
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "sanitize_and_fuzz: installing ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi

# --- configure and build ------------------------------------------------------
# -O1 with line tables only: about 40% less compile time than RelWithDebInfo's
# -O2 -g on the Eigen-heavy files, and reports still name function, file and
# line (docs/fuzzing.md). NDEBUG as in the release build. Without PETSc:
# OpenMPI, which PETSc starts, leaves allocations of its dlopen'ed plugins at
# exit that LeakSanitizer reports; this build checks sinew without PETSc
# instead (the petsc-* solvers absent, asking for one an input error), the
# Release build runs the PETSc tests. The executables of label heavy, which
# the sanitized ctest skips, are not built (SINEW_HEAVY_TESTS=OFF).
# shellcheck disable=SC2086
CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG" \
  -DSINEW_SANITIZE=ON -DSINEW_FUZZ=ON -DSINEW_WITH_PETSC=OFF -DSINEW_HEAVY_TESTS=OFF \
  ${SINEW_ASAN_CMAKE_ARGS:-}
cmake --build "$build" -j "$BUILD_JOBS"

# Reports: symbolized (file:line), UB aborts with a stack, leaks checked.
symbolizer="$(command -v llvm-symbolizer-14 || command -v llvm-symbolizer || true)"
if [ -n "$symbolizer" ]; then export ASAN_SYMBOLIZER_PATH="$symbolizer"; fi
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:check_initialization_order=1:detect_stack_use_after_return=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

status=0

# The kind of a finding, for grouping: its input replayed once (timeouts and
# OOMs are not replayed), reduced to the first line that says what went wrong,
# without addresses and process ids.
finding_signature() {
  local exe="$1" input="$2" name
  name="$(basename "$input")"
  case "$name" in
    timeout-*) echo "timeout (> ${FUZZ_TIMEOUT}s per input)"; return ;;
    oom-*) echo "out of memory (> ${FUZZ_RSS_LIMIT_MB} MB)"; return ;;
    slow-unit-*) echo "slow unit"; return ;;
  esac
  local report line
  report="$(timeout 60 "$exe" -runs=1 "$input" 2>&1 || true)"
  line="$(printf '%s\n' "$report" \
          | grep -E -m1 'runtime error:|terminate called|SUMMARY: (AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer|libFuzzer)' \
          || true)"
  if [ -z "$line" ]; then
    echo "no report when replayed (flaky or state-dependent)"
  else
    printf '%s\n' "$line" | sed -E 's/0x[0-9a-f]+/0x…/g; s/==[0-9]+==//g; s/ *\(BuildId: [0-9a-f]+\)//g'
  fi
}
FUZZ_REPLAY_MAX="${FUZZ_REPLAY_MAX:-50}"

# FUZZ_BAD_INPUT_SEEDS=1: the files of the bad-input corpus (tests/bad_input/cases)
# join the seeds of the target that reads them.
FUZZ_BAD_INPUT_SEEDS="${FUZZ_BAD_INPUT_SEEDS:-0}"
add_bad_input_seeds() {
  local target="$1" corpus="$2" cases=tests/bad_input/cases f n=0
  [ -d "$cases" ] || return 0
  while IFS= read -r -d '' f; do
    case "$target:$f" in
      fuzz_obj:*.obj|fuzz_scene:*.json) ;;
      fuzz_gmsh2:*.msh) sed -n 2p "$f" | grep -q '^2\.' || continue ;;
      fuzz_gmsh4:*.msh) sed -n 2p "$f" | grep -q '^2\.' && continue ;;
      fuzz_tetgen:*.node)
        [ -f "${f%.node}.ele" ] || continue
        { cat "$f"; printf '%s\n' '--ele--'; cat "${f%.node}.ele"; } > "$corpus/bad_input_$n"
        n=$((n + 1)); continue ;;
      *) continue ;;
    esac
    cp "$f" "$corpus/bad_input_$n"
    n=$((n + 1))
  done < <(find "$cases" -type f -print0)
  echo "sanitize_and_fuzz: $target: $n seeds from $cases"
}

# --- the test suite, sanitized ------------------------------------------------
if [ "$SKIP_CTEST" != 1 ]; then
  # Label heavy (solves of the 52k and 206k scenes, studies of many solves:
  # tests/CMakeLists.txt) would take many minutes each under the sanitizers;
  # the Release suite runs them.
  echo "sanitize_and_fuzz: ctest (sanitized, without label heavy), -j $CTEST_JOBS"
  if ! ctest --test-dir "$build" --output-on-failure -j "$CTEST_JOBS" -LE heavy; then
    echo "sanitize_and_fuzz: FAILED: sanitized ctest" >&2
    status=1
  fi
fi

# --- fuzzing --------------------------------------------------------------------
# Each target runs FUZZ_SECONDS on a fresh copy of fuzz/corpus/<target> in
# libFuzzer's fork mode with one worker: a crash, leak, timeout or OOM is saved
# and fuzzing goes on, so one run reports every distinct finding. Findings are
# the files crash-*, leak-*, timeout-*, oom-*, slow-unit-* in <out>/<target>/findings/.
if [ "$SKIP_FUZZ" != 1 ]; then
  summary=()
  for target in $FUZZ_TARGETS; do
    exe="$build/fuzz/$target"
    seeds="fuzz/corpus/$target"
    out="$FUZZ_OUT/$target"
    if [ ! -x "$exe" ] || [ ! -d "$seeds" ]; then
      echo "sanitize_and_fuzz: no executable $exe or no seeds $seeds" >&2
      status=1
      continue
    fi
    rm -rf "$out"
    mkdir -p "$out/corpus" "$out/findings"
    cp "$seeds"/* "$out/corpus/"
    if [ "$FUZZ_BAD_INPUT_SEEDS" = 1 ]; then add_bad_input_seeds "$target" "$out/corpus"; fi
    echo "sanitize_and_fuzz: $target for ${FUZZ_SECONDS}s (log: $out/fuzz.log)"
    set +e
    "$exe" "$out/corpus" \
      -max_total_time="$FUZZ_SECONDS" -timeout="$FUZZ_TIMEOUT" -rss_limit_mb="$FUZZ_RSS_LIMIT_MB" \
      -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
      -artifact_prefix="$out/findings/" -print_final_stats=1 \
      > "$out/fuzz.log" 2>&1
    code=$?
    set -e
    findings=$(find "$out/findings" -maxdepth 1 -type f \
                 \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' -o -name 'slow-unit-*' \) | wc -l)
    corpus=$(find "$out/corpus" -type f | wc -l)
    # The last status line of fork mode: "#<execs>: cov: … exec/s … oom/timeout/crash: a/b/c time: Ns"
    last=$(grep -E '^#[0-9]+: cov:' "$out/fuzz.log" | tail -1 || true)
    summary+=("$target: exit $code, findings $findings, corpus $corpus files; ${last:-no status line}")
    if [ "$findings" -gt 0 ] || [ "$code" -ne 0 ]; then
      echo "sanitize_and_fuzz: FAILED: $target (exit $code, $findings findings in $out/findings)" >&2
      # Fork mode saves every crashing input, many of one bug: group them by
      # kind (up to FUZZ_REPLAY_MAX replays) into findings/summary.txt.
      set +e
      find "$out/findings" -maxdepth 1 -type f ! -name summary.txt | sort | head -n "$FUZZ_REPLAY_MAX" \
        | while read -r input; do
            printf '%s\t%s\n' "$(finding_signature "$exe" "$input")" "$input"
          done \
        | sort | awk -F'\t' '{ n[$1]++; if (!($1 in first)) first[$1] = $2 }
                              END { for (s in n) printf "%5d  %s\n       e.g. %s\n", n[s], s, first[s] }' \
        > "$out/findings/summary.txt"
      set -e
      cat "$out/findings/summary.txt" >&2
      status=1
    fi
  done
  echo "sanitize_and_fuzz: fuzz summary (${FUZZ_SECONDS}s per target)"
  for line in "${summary[@]}"; do echo "  $line"; done
fi

exit $status
