// Writes model/contact/fft_wisdom.inc to standard output: FFTW_PATIENT plans of the DC-FFT
// convolutions of the grid shapes the studies use most (the cycloid LTCA's 40 × 40 and its coarse
// 24 × 24; the LCR half_space check's 48 × 128 and its verification's 96 × 256), as FFTW wisdom.
// Run by scripts/fft_wisdom.sh on the reference machine; the plans are imported by every
// HalfSpaceSolver (model/contact/half_space.h, FftWisdomImported).
#include <iostream>

#include "model/contact/half_space.h"

int main() {
  const std::string wisdom = camopt::contact::PlanFftWisdom({{40, 40}, {24, 24}, {48, 128}, {96, 256}});
  std::cout << "// FFTW wisdom of the contact convolutions (half_space.cc, FftWisdomImported): written by\n"
               "// `scripts/fft_wisdom.sh`; do not edit.\n"
               "R\"wisdom("
            << wisdom << ")wisdom\"\n";
  return 0;
}
