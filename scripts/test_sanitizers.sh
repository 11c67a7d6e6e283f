#!/usr/bin/env bash
# Builds the test suite with AddressSanitizer + UndefinedBehaviorSanitizer in build-asan/ (CMake
# option CAMOPT_SANITIZE) and runs it. Exits non-zero when a test fails or a sanitizer reports
# (UBSan is built not to recover, ASan aborts on its first report). .ci/run calls it after the
# README's test command. `bash scripts/test_sanitizers.sh --all` runs every test, long ones too.
#
# Cost (2 cores, 2026-11-25, docs/reliability.md): the build at -O2 -g took 18 min and the whole
# suite under the sanitizers 15 min here, and on CI more than the rest of the run together. So the
# build is -O1 with line tables only (-g1: reports still give file:line), and the run leaves out
# the tests that repeat whole studies over and over: each example at every convergence setting,
# the sizing examples run twice, sweeps run three or four times over, the readers in Python and
# Chromium. Those
# took 80% of the sanitized suite's time; the code they run is run under the sanitizers by the
# lighter tests of the same kind (unit tests of each stage, the other examples' convergence runs,
# one end-to-end run of every study kind, a sweep of 6 cases). The README's test command runs
# them all, in Release.
set -euo pipefail
cd "$(dirname "$0")/.."
CXX_SAN="${CXX_SAN:-}"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DCAMOPT_SANITIZE=ON -DCAMOPT_BUILD_BENCH=OFF ${CXX_SAN:+-DCMAKE_CXX_COMPILER="$CXX_SAN"} >/dev/null
cmake --build build-asan -j"$(nproc)"
# Leak checking is off: the libraries (Ceres/glog, Ipopt) keep allocations to exit, and a CLI run
# is one process. Container-overflow checks are off: Ceres and NLopt are not instrumented, and
# vectors passed across that boundary give false reports.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=0:detect_container_overflow=0:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# Left out under the sanitizers (each took 10 s or more there; what still covers its code):
long_tests=(
  # convergence runs of the heavy examples; lcr_i matches lcr_i, lcr_ii, lcr_ii_crowned and
  # lcr_ii_tolerances (the other 15 examples' convergence runs stay)
  'EveryExample/ConvergenceOfExample\.CoarseSettings/(cycloid_ltca_nnm_|lcr_i|lcr_min_size_crowned|lcr_min_size_robust|lcr_min_size_straight3d)'
  # two runs of the 3D and catalogue sizing examples (LcrSizing3D and LcrMinSize.Catalogue* stay)
  'EveryExample/TwoRuns\.GiveByteIdenticalFolders/(lcr_crowning_tuning|lcr_min_size_catalogue|lcr_min_size_crowned|lcr_min_size_straight3d|cycloid_min_size_)'
  # sweeps run three or four times over: resumed, on 1/2 threads and 2 MPI ranks, of sizing cases
  # (SweepRun.FailingCases* and the other SweepCli tests stay)
  '^SweepRun\.(ResumeAfterSigint|OneAndTwoThreadsAndTwoRanks|LcrMinSizeCasesOnTwoThreads)'
  '^SweepCli\.AnOutputFolderHoldingOtherFilesIsRefusedBeforeAnyCase'
  # whole cycloid sizings (10-15 s each in Release; the rows' derivative tests stay)
  '^CycloidMinSize\.(PaperDriveSized|Ratio29Crowning|IpoptAndSlsqp)'
  # the study kind's end-to-end run (two sizings and the best design's cycloid_ltca run; its
  # exit-3 run and both examples' convergence runs stay)
  '^CycloidMinSizeStudy\.SmallStudyEndToEnd'
  # many Ipopt/NLopt sizings of LCR II (the other LcrMinSize tests stay)
  '^LcrMinSize\.(ImpossibleLimitsGiveNoBestAndSayWhy|BackendsAgreeAndGradientsSaveEvaluations)'
  '^LcrCrowningTuning\.LcrIIAt80NmUncrownedVersusTuned'
  # the verified sizing of every example and of one variant with two backends, the cycloid error
  # estimate against 1024-angle references, a second sweep beside a running one
  # (Verification.StraightRollers*/CrowningCoefficientRangeFromZero* run the 3D verification loop,
  # the cycloid examples' two runs the refined error estimate, SweepRun.FailingCases* a sweep)
  '^Verification\.(ShortLogCrownWithoutOverloadIsVerifiedAndBackendsAgree|EverySizingAndTuningExampleIsVerified)'
  '^CycloidErrorEstimate\.' '^SweepRun\.ASecondSweepIntoTheSameFolder'
  # every example's STEP solid read back (407 s under the sanitizers: every study run whole, the
  # sizing examples with their verification; GeometryFiles.LcrIIStepSolidsReadBack,
  # CycloidNnmDiscStepSolid and DiscCamStepSolidAndCutterPath stay)
  '^GeometryFiles\.EveryExampleStepSolidReadsBack'
  # Python's and Chromium's readers of the files (the writers' C++ tests stay)
  '^GeometryFiles\.IndependentReaders' '^Report\.renders_in_chromium'
)
exclude=""
if [[ "${1:-}" != "--all" ]]; then
  exclude=$(IFS='|'; echo "${long_tests[*]}")
fi
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" ${exclude:+-E "$exclude"}
