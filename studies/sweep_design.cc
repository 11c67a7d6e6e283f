#include "studies/sweep_design.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include <boost/random/sobol.hpp>

namespace camopt::studies::sweep {

using nlohmann::json;

namespace {
// The value of a level: rounded to a whole number on request.
json Level(double x, const Variation& v) {
  if (v.integer) return json(static_cast<int64_t>(std::llround(x)));
  return json(x);
}

// A point u in [0, 1) mapped onto a variation: across its range, or onto one of its values.
json AtFraction(const Variation& v, double u) {
  if (v.has_range) {
    const double x = v.log ? std::exp(std::log(v.lo) + u * (std::log(v.hi) - std::log(v.lo)))
                           : v.lo + u * (v.hi - v.lo);
    return Level(x, v);
  }
  const size_t n = v.values.size();
  return v.values[std::min(n - 1, static_cast<size_t>(u * static_cast<double>(n)))];
}

// A double in [0, 1) from 53 bits of the generator (the standard's distributions are not the same
// on every library; this is).
double Uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace

std::vector<json> RangeLevels(const Variation& v, int count) {
  std::vector<json> levels;
  for (int k = 0; k < count; ++k) {
    const double u = count == 1 ? 0.0 : static_cast<double>(k) / (count - 1);
    const double x = v.log ? std::exp(std::log(v.lo) + u * (std::log(v.hi) - std::log(v.lo)))
                           : v.lo + u * (v.hi - v.lo);
    levels.push_back(Level(k == count - 1 && count > 1 ? v.hi : x, v));
  }
  return levels;
}

std::vector<std::vector<json>> Cases(const Sweep& s) {
  std::vector<std::vector<json>> cases;
  const size_t dims = s.vary.size();
  if (s.design == "factorial") {
    // The first field varies slowest: the cases read like nested loops in the order written.
    std::vector<size_t> at(dims, 0);
    while (true) {
      std::vector<json> c;
      for (size_t d = 0; d < dims; ++d) c.push_back(s.vary[d].values[at[d]]);
      cases.push_back(std::move(c));
      size_t d = dims;
      while (d > 0) {
        --d;
        if (++at[d] < s.vary[d].values.size()) break;
        at[d] = 0;
        if (d == 0) return cases;
      }
      if (dims == 0) return cases;
    }
  }
  if (s.design == "zip") {
    for (size_t i = 0; i < s.vary.front().values.size(); ++i) {
      std::vector<json> c;
      for (const Variation& v : s.vary) c.push_back(v.values[i]);
      cases.push_back(std::move(c));
    }
    return cases;
  }
  const size_t n = static_cast<size_t>(s.samples);
  std::vector<std::vector<double>> u(n, std::vector<double>(dims));
  if (s.design == "latin_hypercube") {
    // One sample in each of n equal strata of every field; the strata are paired at random
    // (a permutation per field) and each sample is placed at random within its stratum.
    std::mt19937_64 rng(s.seed);
    for (size_t d = 0; d < dims; ++d) {
      std::vector<size_t> strata(n);
      for (size_t i = 0; i < n; ++i) strata[i] = i;
      for (size_t i = n; i > 1; --i) std::swap(strata[i - 1], strata[rng() % i]);  // Fisher-Yates
      for (size_t i = 0; i < n; ++i)
        u[i][d] = (static_cast<double>(strata[i]) + Uniform(rng)) / static_cast<double>(n);
    }
  } else {
    // Boost.Random's Sobol sequence (its own table of direction numbers); the first point (the
    // origin, a corner of the box) is skipped.
    boost::random::sobol gen(dims);
    gen.discard(dims);
    for (size_t i = 0; i < n; ++i)
      for (size_t d = 0; d < dims; ++d) u[i][d] = std::ldexp(static_cast<double>(gen()), -64);
  }
  for (size_t i = 0; i < n; ++i) {
    std::vector<json> c;
    for (size_t d = 0; d < dims; ++d) c.push_back(AtFraction(s.vary[d], std::min(u[i][d], 1.0 - 0x1.0p-53)));
    cases.push_back(std::move(c));
  }
  return cases;
}

}  // namespace camopt::studies::sweep
