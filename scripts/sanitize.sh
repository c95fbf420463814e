#!/usr/bin/env bash
# A representative subset of the test suite under AddressSanitizer +
# UndefinedBehaviorSanitizer, then the libFuzzer harnesses (fuzz/) for a
# bounded time with a seed corpus made from cases/. Built with clang into
# build-sanitize/ (one build serves both: the library is instrumented for the
# sanitizers and for coverage). Any sanitizer report, test failure or fuzzer
# finding fails the script. The Release suite (scripts/test.sh) runs every
# test; this stage runs the folders that read input, own memory or call C
# libraries, so that CI stays within its time (about 35 min on 2 cores).
#
#   RAILSTAB_SANITIZE_DIRS  test folders built and run (a semicolon list, the
#                           default below: input readers and hostile input,
#                           the command line (which runs the instrumented
#                           executable, so every command's code path), the
#                           contact, element and track code, the SUNDIALS
#                           integrators, the periodic orbits (nonlinear: the
#                           normal-form and Bautin orbits, both ways of
#                           integrating the variational equations, the Hopf
#                           coefficients), steady curving and the scene's
#                           setup; left out: check, model, ride, stability,
#                           report, reference, linear, sensitivity, study,
#                           extreme, cases and verify, whose code the
#                           command-line tests run too; CI took 34 of its 35
#                           minutes with them)
#   RAILSTAB_FUZZ_SECONDS   time per harness (default 30: 60 s in total)
#   RAILSTAB_SANITIZE_SKIP  ctest -E regex of tests left out within those
#                           folders (default below: the long time-domain
#                           runs (the assessment's two runs among them), 10-20 s each in Release and 100-200 s under
#                           ASan (and the time-domain runs of 15-55 s under
#                           ASan whose code shorter tests run: the Hopf
#                           amplitude checks, the ramps, the limit-cycle
#                           error, the frame-independence run), the
#                           thesis-vehicle periodic orbits, the S1002
#                           profile-contact orbits and the bogie's monodromy
#                           against central differences (6-52 s each in
#                           Release; the normal-form orbit tests run the same
#                           code and stay in), the steady-curving sweeps and continuations
#                           (20-80 s each under ASan; the curving command's
#                           tests in cli/ and the short curving tests run
#                           that code), the tests
#                           that assert a CPU time or a CPU budget, which the
#                           sanitizers' ~10x slowdown breaks, and the
#                           packaging tests)
set -euo pipefail
cd "$(dirname "$0")/.."
fuzz_seconds=${RAILSTAB_FUZZ_SECONDS:-30}
long_runs='CliRunErrors\.ReachingTheTableEdge|CliAssess\.|CliIrregularTrack\.|SteadyCurvingProfiles\.EquilibriumIsWhere|SteadyCurvingCoach\.(EquilibriumCommand|SweepFrom|IssuePointFound)|SteadyCurvingThesisVehicle\.|CriticalSpeedSensitivity\.ThesisVehicle|ContactDamping\.VerifyInTheArc|ThesisBogie\.ShiftsOutwardsInCurve|ExtremeConservative|Extreme/ExtremeRun|Verification\.|ErrorEstimate\.|ExtremeNearCritical|CurveStabilityProfiles\.(SpinMode|VehicleArc|HighSpeed)|CliVerifyAnyMode|OrbitContinuationThesisVehicle\.|ProfileContactOrbit\.|FlowSensitivity\.Monodromy|BifurcationAnalysisThesisBogie\.|HopfThesisVehicle\.TimeDomain|HopfBrusselator\.PredictedAmplitude|SpeedRamp\.HuntingEnds|CliSpeedRamp\.(TwoRates|S1002Bogie)|LimitCycleError\.AmplitudeAndPeriod|BodyDynamics\.CurveResultIndependent|SparseNewtonRun\.FollowsTheDenseRunWithinTheTolerance/..thesis_train_4'
timed='ContactTables\.BuildTakesUnderOneSecond|SundialsFlagNames|WorkLimits'
# Packaging and build tests (the example programs, install + find_package,
# the compile-fail test of the element contract): about the
# Release build's install tree, not about memory errors; the Release suite
# runs them (an ASan library cannot be linked by an uninstrumented consumer).
packaging='^example_critical_speed$|^example_eigen_at_speed$|^install_and_find_package$|^compile_fail_'
skip=${RAILSTAB_SANITIZE_SKIP:-"$long_runs|$timed|$packaging"}
build=build-sanitize

dirs=${RAILSTAB_SANITIZE_DIRS:-"cli;hostile;scene;scene_reading;io;profiles;contact_geometry;contact;elements;track;integrate;nonlinear;curving;setup"}

# The Python module stays out: an ASan-built extension needs the ASan runtime
# preloaded into the interpreter, and the Release suite tests it.
CC=clang CXX=clang++ cmake -S . -B $build -DCMAKE_BUILD_TYPE=Release -DRAILSTAB_SANITIZE=ON \
  -DRAILSTAB_BUILD_BENCHMARKS=OFF -DRAILSTAB_BUILD_EXAMPLES=OFF -DRAILSTAB_BUILD_PYTHON=OFF \
  "-DRAILSTAB_TEST_DIRS=$dirs" >/dev/null
cmake --build $build -j2 --target railstab_tests railstab fuzz_scene fuzz_profile

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
echo "== tests in $dirs under ASan + UBSan (left out: $skip)" >&2
(cd $build && ctest -j2 --output-on-failure -E "$skip")

echo "== libFuzzer: ${fuzz_seconds} s per harness" >&2
run_fuzzer() {  # name, max input length, seed files...
  local name=$1 max_len=$2; shift 2
  local work=$build/fuzz_runs/$name
  rm -rf "$work" && mkdir -p "$work/corpus" "$work/seeds" "$work/artifacts"
  cp "$@" "$work/seeds/"
  # -timeout: an input taking longer is a hang (a finding); -rss_limit_mb:
  # runaway memory is a finding too.
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
    $build/fuzz_$name -max_total_time="$fuzz_seconds" -timeout=20 -rss_limit_mb=2048 \
    -max_len="$max_len" -print_final_stats=1 -artifact_prefix="$work/artifacts/" \
    "$work/corpus" "$work/seeds" 2>"$work/log" || {
      tail -n 60 "$work/log" >&2
      echo "fuzz_$name: FINDING (input saved in $work/artifacts/)" >&2
      return 1
    }
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$work/log" >&2 || true
  echo "fuzz_$name: no finding in ${fuzz_seconds} s" >&2
}
run_fuzzer scene 16384 cases/*.toml
# Profile seeds: the first byte picks the reader (0 .prw, 1 .prr, 2 plain mm).
seeds=$build/fuzz_runs/profile_seeds && rm -rf $seeds && mkdir -p $seeds
{ printf '\0'; cat cases/profiles/MBench_S1002_v3.prw; } > $seeds/s1002.prw
{ printf '\1'; cat cases/profiles/MBench_UIC60_v3.prr; } > $seeds/uic60.prr
printf '\2# y z in mm\n-30 1\n-20 0.5\n0 0\n20 -0.5\n30 -1\n' > $seeds/plain.txt
run_fuzzer profile 65536 $seeds/*
