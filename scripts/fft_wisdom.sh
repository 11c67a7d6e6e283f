#!/usr/bin/env bash
# Records the contact convolutions' FFT plans (FFTW_PATIENT) into model/contact/fft_wisdom.inc:
#   scripts/fft_wisdom.sh [BUILD_DIR]
# Run on an idle machine of the kind the program runs on; then rebuild. The plans change the last
# digits of half_space results (not their accuracy): compare the examples before committing
# (scripts/compare_examples.sh). docs/performance.md "FFT plans".
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
cmake --build "$build" --target camopt_fft_wisdom
"$build/camopt_fft_wisdom" > model/contact/fft_wisdom.inc.new
mv model/contact/fft_wisdom.inc.new model/contact/fft_wisdom.inc
echo "model/contact/fft_wisdom.inc: $(wc -c < model/contact/fft_wisdom.inc) bytes"
