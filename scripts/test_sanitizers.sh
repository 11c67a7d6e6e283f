#!/usr/bin/env bash
# Builds the test suite with AddressSanitizer + UndefinedBehaviorSanitizer in build-asan/ (CMake
# option CAMOPT_SANITIZE) and runs it. Exits non-zero when a test fails or a sanitizer reports
# (UBSan is built not to recover, ASan aborts on its first report). .ci/run calls it after the
# README's test command. `bash scripts/test_sanitizers.sh --all` runs every test, long ones too;
# `--list` prints the tests left out.
#
# Cost (2 cores, 2026-11-25, docs/reliability.md): the build at -O2 -g took 18 min and the whole
# suite under the sanitizers 15 min here, and on CI more than the rest of the run together. So the
# build is -O1 with line tables only (-g1: reports still give file:line; GCC's variable tracking
# off, executables not position-independent; the study and test files at -Og, the test files under
# ASan only: CMakeLists.txt, CAMOPT_SANITIZE), and the run leaves out the tests that repeat whole
# studies over and over: each example at every convergence setting, the sizing examples run twice,
# sweeps run three or four times over, the readers in Python and Chromium. Those took 80% of the
# sanitized suite's time; the code they run is run under the sanitizers by the lighter tests of the
# same kind (unit tests of each stage, the other examples' convergence runs, one end-to-end run of
# every study kind, a sweep of 6 cases). The README's test command runs them all, in Release.
set -euo pipefail
cd "$(dirname "$0")/.."
CXX_SAN="${CXX_SAN:-}"
# Test files every test of which is left out below (long_tests): not compiled at all for this pass
# (about a sixth of the test code; each test name they define must match a pattern of long_tests,
# checked below). `--all` compiles and runs them.
skipped_files=(tests/serve_test.cc tests/sweep_test.cc tests/status_test.cc
               tests/schema_parser_agreement_test.cc tests/cycloid_error_estimate_test.cc
               tests/lcr_crowning_tuning_test.cc)
skip_list=$(IFS=';'; echo "${skipped_files[*]}")
[[ "${1:-}" != "--all" ]] || skip_list=""
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DCAMOPT_SANITIZE=ON -DCAMOPT_BUILD_BENCH=OFF "-DCAMOPT_SANITIZED_SKIP_TEST_FILES=$skip_list" \
  ${CXX_SAN:+-DCMAKE_CXX_COMPILER="$CXX_SAN"} >/dev/null
# --list: what would run, from the build as it stands (nothing built or run)
[[ "${1:-}" == "--list" ]] || cmake --build build-asan -j"$(nproc)"
# Leak checking is off: the libraries (Ceres/glog, Ipopt) keep allocations to exit, and a CLI run
# is one process. Container-overflow checks are off: Ceres and NLopt are not instrumented, and
# vectors passed across that boundary give false reports.
# The quarantine of freed memory is 16 MB instead of ASan's 256 MB: a use after free is still caught
# while the block is among the last 16 MB freed, and the suite's allocation-heavy tests no longer
# fault in fresh pages for every allocation (LcrRatings.EstimatedErrorsBoundTheConvergedRatings
# 8.6 → 4.2 s, 214 000 → 50 000 page faults, 2026-12-01). `--all` (nightly) keeps ASan's 256 MB.
quarantine=":quarantine_size_mb=16"
[[ "${1:-}" != "--all" ]] || quarantine=""
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=0:detect_container_overflow=0:abort_on_error=1$quarantine}"
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
  # a slower sweep into a folder a file is added to while it runs (the swap's check; the other
  # output-folder tests of the sweep and of camopt run stay)
  '^SweepCli\.AFileAddedWhileTheSweepRunsIsKept'
  # whole cycloid sizings and tunings re-solved at moved limits, with their limit costs'
  # re-solves (Status.ExitCodes*, AnAnalysis*, AVerifiedSizing*, ATuningWithout* stay)
  '^Status\.(ACycloidSizingWithItsLimitsMoved|LimitCostsAgreeWithCentralReSolve|OneFieldEditsOfTheCrowningTuning)'
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
  # (Verification.StraightRollers* runs the 3D verification loop,
  # the cycloid examples' two runs the refined error estimate, SweepRun.FailingCases* a sweep)
  '^Verification\.(ShortLogCrownWithoutOverloadIsVerifiedAndBackendsAgree|EverySizingAndTuningExampleIsVerified)'
  '^CycloidErrorEstimate\.' '^SweepRun\.ASecondSweepIntoTheSameFolder'
  # every example's STEP solid read back (407 s under the sanitizers: every study run whole, the
  # sizing examples with their verification; GeometryFiles.LcrIIStepSolidsReadBack,
  # CycloidNnmDiscStepSolid and DiscCamStepSolidAndCutterPath stay)
  '^GeometryFiles\.EveryExampleStepSolidReadsBack'
  # Python's and Chromium's readers of the files (the writers' C++ tests stay)
  '^GeometryFiles\.IndependentReaders' '^Report\.renders_in_chromium'
  # the studio in Chromium: its Play checks are timing judgments (after 4 s the drawing comes from
  # the run's whole revolution, at 200 ms latency), which a server 2-10x slower under the sanitizers
  # missed on CI (2026-12-01); the server's code runs sanitized in RequestFuzz and the request
  # corpus replay
  '^Studio\.browser_end_to_end'
  # the second and third example of a kind run twice through the command line (each kind's first
  # example stays: lcr_ii, lcr_min_size_catalogue, cycloid_ltca_nnm_lcm/_fcm, ...; the tolerance,
  # robust and life sizings keep their unit tests and coarse convergence runs; the life sizing's two
  # runs were the longest sanitized test, 81 s)
  'EveryExample/TwoRuns\.GiveByteIdenticalFolders/(lcr_i|lcr_ii_crowned|lcr_ii_tolerances|lcr_min_size|lcr_min_size_robust|lcr_min_size_life|cycloid_ltca_nnm_pcm|cycloid_ltca_nnm_none) '
  # the command line's --convergence on whole examples (ConvergenceOfExample runs the same code on
  # every light example) and the life sizing at every convergence setting (its unit tests stay)
  '^Convergence\.(CommandLine|RefinementOverTheWorkLimitIsSkipped)'
  'EveryExample/ConvergenceOfExample\.CoarseSettings/(lcr_min_size_life|disc_cam_translating) '
  # more whole LCR sizings (DefaultReachesTheExactOptimum and the
  # 3D sizing's independent check stay)
  '^LcrMinSizeLife\.(LifeLimitBindsAndCostsDiameter|AHardLifeLimitSkipsTheCombinationsOutOfReach)'
  # every sizing example run whole and its design re-analysed at twice the grid and angles
  '^EveryExample/SizingExample\.'
  '^LcrMinSize\.(RatioMinus90BestSatisfiesEveryLimitInLcrAnalysis|EfficiencyLimitIsHeld)'
  '^LcrSizing3D\.CrownRadiusAndCamThicknessVariablesIpoptAndSlsqpAgree'
  # camopt init's template of every kind run whole (the templates are examples that run above;
  # Init.UnknownKind* stays)
  '^Init\.EveryKindsStudyRuns'
  # each datasheet limit of the cycloid sizing made to bind (four sizings and their cycloid_ltca
  # runs; CycloidMinSize.OutputMechanismRowsDerivativesMatchCentralDifferences stays), the
  # tolerance example's Monte-Carlo run twice (the CycloidTransmissionError tests stay) and the
  # oscillating sizing's convergence runs (DiscCamMinSize's oscillating tests stay)
  '^CycloidMinSizeStudy\.EachDatasheetLimitBindsIsVerifiedAndIsWhatCycloidLtcaReports'
  'EveryExample/TwoRuns\.GiveByteIdenticalFolders/cycloid_ltca_nnm_tolerances'
  'EveryExample/ConvergenceOfExample\.CoarseSettings/disc_cam_min_size_oscillating'
  # the sweep files' fixed-seed mutation campaign (500 sweeps; the studies' campaign and the sweep
  # corpus replay stay)
  '^MutationFuzz\.SweepFilesFixedSeed'
  # three quarters of the studies' fixed-seed mutation campaign: shards 1, 2 and 3 (43-50 s each
  # sanitized, 2026-12-02, the longest sanitized tests after the examples' runs); shard 0 and the
  # corpus of past failures stay, and the Release suite runs all four shards
  '^MutationFuzz\.FixedSeedShard[123]'
  # whole lubricated sizings (each example twice and at its coarse settings, and each binding
  # efficiency limit against the same sizing without it: 500 s of the sanitized suite's CPU, 2026-11-29;
  # the LCR efficiency objective's example against the same study minimising the outer diameter);
  # the lubricated rows' derivative tests, the rows against the dense check and each kind's sizing
  # that ends without a thermal equilibrium (exit 3) stay
  '^CycloidMinSizeStudy\.AMinEfficiencyThatBindsCostsSizeIsVerifiedAndIsWhatCycloidLtcaReports'
  '^LcrMinSizeLubrication\.AMinEfficiencyThatBindsCostsSizeAndIsWhatLcrAnalysisReports'
  '^LcrMinSizeEfficiency\.TheExampleLosesLeastIsWhatLcrAnalysisReportsAndNoFeasibleMoveLosesLess'
  'EveryExample/TwoRuns\.GiveByteIdenticalFolders/(lcr_min_size_lubricated|lcr_min_size_efficiency)'
  'EveryExample/ConvergenceOfExample\.CoarseSettings/(lcr_min_size_lubricated|lcr_min_size_efficiency|cycloid_min_size_lubricated)'
  # the field-by-field sample at full caps: runs of up to 10 s in Release judged against a 30 s CPU
  # limit (x5 under the sanitizers), which a 10-20x slower sanitized run can exceed (an
  # lcr_crowning_tuning edit did, 2026-11-29); it is a timing judgment, run by the Release suite
  '^MutationFields\.Shard'
  # End-to-end suites whose code other sanitized tests reach, so that CI's pass stays within its
  # time (issue of 2026-11-30: .ci/run 64 min against 45; this tier was 40% of the sanitized run):
  # the studio's server (RequestFuzz and the request corpus replay run it sanitized), the schema
  # and parser agreement over thousands of generated studies (the study corpus replay and the
  # mutation campaign parse sanitized), the exit statuses of whole re-solved studies and every
  # example at its coarse settings (each kind's example run twice stays), and the sweeps (the sweep
  # corpus replay stays). This supersedes the "stay" of the sweep, status and convergence lines
  # above; `--all` (nightly) runs them.
  '^Serve\.' '^SchemaParserAgreement\.' '^Status\.' '^Sweep(Cli|Run|Design|Input|Pareto|Report)\.'
  '^EveryExample/ConvergenceOfExample\.'
  # Second and third whole solves of a kind (the sanitized suite's longest tests on CI, 2026-12-01:
  # 440 s of its 2100 s of test time). Each kind keeps one sanitized end-to-end sizing or design:
  # LcrMinSize.DefaultReachesTheExactOptimum (and the line-model sizing's other tests),
  # LcrSizing3D.CrownedSizingHoldsTheLimitsUnderAnIndependentCheck,
  # Verification.StraightRollersUnderMisalignment*, SizingRatings.LcrMomentaryTorqueLimit* and both
  # cycloid SizingRatings, DiscCamMinSize.InLineBaseCircleMatchesTheClosedForm and the oscillating
  # sizing's bisection, DiscCamMotion.LeastResidualVibrationBeatsEveryNamedLaw*, CycloidRatings'
  # and CycloidTuningStudy's other tests, LcrRatings.EstimatedErrorsBoundTheConvergedRatings. These
  # repeat those code paths on more designs or backends.
  '^DiscCamMotion\.LeastResidualVibrationIsAZeroOfTheDesignedLawsSpectrum'
  # a motion design whose pressure-angle limit is out of reach, run whole (6.5 s in Release; the
  # tightening's guard is a comparison, and the loop around it runs sanitized in the other tests)
  '^DiscCamMotion\.APressureAngleLimitFarOutOfReachIsNotVerifiedAndNamed'
  '^SizingRatings\.LcrSizedReducerReachesTheRatedTorqueAsLcrAnalysisSolvesIt'
  '^LcrSizing3D\.(CrownedExamplePrunesTheCombinationsAboveTheBest|APolishStoppedAtABoundContinuesToTheSameDesign)'
  '^LcrMinSize\.(LimitSensitivityMatchesResolving|AtLeastAsGoodAsABruteForceGrid|OutputsAreByteIdentical)'
  '^DiscCamMinSize\.(ByteIdenticalAndTheBestDesignRunsAsDiscCam|AnOffsetPaysOnlyForAnAsymmetricProgram|OscillatingExampleIpoptAgreesWithSlsqp)'
  '^CycloidRatings\.EstimatedErrorsBoundTheRatingsOfAFinerModel'
  '^CycloidTuningStudy\.ExamplesAreVerifiedByTheAccurateModel'
  '^DiscCamOscillatingRollerLoads\.SizingStressLimitIpoptAgreesWithSlsqpAndTheMechanism'
  '^Verification\.CrowningCoefficientRangeFromZeroIsAcceptedAndMessagesReadWell'
  '^CliMessages\.SizingSummaryNamesWhatBindsInPlainWordsAndWhatItCosts'
)
# (The builds that run no camopt code, InstalledHeaders, ConsumerProject and ApiReference, are not
# registered in this build at all: cmake/camopt_package.cmake, cmake/camopt_docs.cmake.)
# ctest's own -E silently matches nothing when its regular expression grows past CMake's size limit
# (this list did, at 1.5 kB), so the names are matched here with grep and the kept tests passed to
# ctest by number; a pattern that matches no test is an error (a renamed test would otherwise run
# again under the sanitizers, or a typo leave a long one in).
listing=$(ctest --test-dir build-asan -N | sed -n 's/^ *Test *#\([0-9]*\): \(.*\)$/\1 \2/p')
total=$(echo "$listing" | wc -l)
if [[ "${1:-}" == "--all" ]]; then
  ctest --test-dir build-asan --output-on-failure -j"$(nproc)"
  exit
fi
# (A here-string, not a pipe: `grep -q` stops reading at its first match, and under pipefail the
# writer's SIGPIPE would count as "no match".)
names=$(echo "$listing" | cut -d' ' -f2-)
# The tests of the files not compiled here, by their TEST(Suite, Name) lines (none is parameterised).
skipped_names=$(grep -ohE '^(TEST|TEST_F)\( *[A-Za-z0-9_]+, *[A-Za-z0-9_]+' "${skipped_files[@]}" \
                | sed -E 's/^[A-Z_]+\( *//; s/, */./')
for p in "${long_tests[@]}"; do
  if ! grep -Eq -- "$p" <<< "$names"$'\n'"$skipped_names"; then
    echo "test_sanitizers.sh: the pattern '$p' matches no test" >&2
    exit 1
  fi
done
pattern=$(IFS='|'; echo "${long_tests[*]}")
not_left_out=$(grep -Ev -- "$pattern" <<< "$skipped_names" || true)
if [[ -n "$not_left_out" ]]; then
  echo "test_sanitizers.sh: tests of a file not compiled here that long_tests does not leave out:" >&2
  echo "$not_left_out" >&2
  exit 1
fi
numbers=$(echo "$listing" | cut -d' ' -f1)
kept_lines=$(echo "$listing" | cut -d' ' -f2- | grep -Evn -- "$pattern" | cut -d: -f1)
kept=$(echo "$numbers" | sed -n "$(echo "$kept_lines" | sed 's/$/p/' | paste -sd';')" | paste -sd,)
skipped_count=$(grep -c . <<< "$skipped_names")
left_out=$((total - $(echo "$kept" | tr ',' '\n' | wc -l) + skipped_count))
total=$((total + skipped_count))
echo "sanitized suite: $((total - left_out)) of $total tests ($left_out long ones left out, $skipped_count of them in files not compiled here)"
if [[ "${1:-}" == "--list" ]]; then  # the selection only, nothing run: the tests left out
  echo "$listing" | cut -d' ' -f2- | grep -E -- "$pattern"
  echo "$skipped_names"
  exit
fi
# The kept gtest tests run a gtest suite's tests (up to 8) per process: a sanitized start costs
# about 0.3 s of CPU, which one process per test paid about 1000 times (scripts/ctest_in_groups.py).
python3 scripts/ctest_in_groups.py build-asan build-asan/grouped "$kept"
ctest --test-dir build-asan/grouped --output-on-failure -j"$(nproc)"
