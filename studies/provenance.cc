#include "studies/provenance.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>

#ifndef CAMOPT_VERSION_STRING
#error "CAMOPT_VERSION_STRING is set by cmake/camopt_schemas.cmake"
#endif

namespace camopt::studies {

std::string CamoptVersion() { return CAMOPT_VERSION_STRING; }

namespace {

// FIPS 180-4, section 4.2.2: the first 32 bits of the fractional parts of the cube roots of the
// first 64 primes.
constexpr std::array<uint32_t, 64> kRound = {
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
    0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
    0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
    0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
    0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
    0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2};

constexpr uint32_t Rotr(uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

void Compress(std::array<uint32_t, 8>& h, const unsigned char* block) {
  uint32_t w[64];
  for (int t = 0; t < 16; ++t)
    w[t] = uint32_t(block[4 * t]) << 24 | uint32_t(block[4 * t + 1]) << 16 |
           uint32_t(block[4 * t + 2]) << 8 | uint32_t(block[4 * t + 3]);
  for (int t = 16; t < 64; ++t) {
    const uint32_t s0 = Rotr(w[t - 15], 7) ^ Rotr(w[t - 15], 18) ^ (w[t - 15] >> 3);
    const uint32_t s1 = Rotr(w[t - 2], 17) ^ Rotr(w[t - 2], 19) ^ (w[t - 2] >> 10);
    w[t] = w[t - 16] + s0 + w[t - 7] + s1;
  }
  uint32_t a = h[0], b = h[1], c = h[2], d = h[3], e = h[4], f = h[5], g = h[6], k = h[7];
  for (int t = 0; t < 64; ++t) {
    const uint32_t t1 = k + (Rotr(e, 6) ^ Rotr(e, 11) ^ Rotr(e, 25)) + ((e & f) ^ (~e & g)) + kRound[t] + w[t];
    const uint32_t t2 = (Rotr(a, 2) ^ Rotr(a, 13) ^ Rotr(a, 22)) + ((a & b) ^ (a & c) ^ (b & c));
    k = g;
    g = f;
    f = e;
    e = d + t1;
    d = c;
    c = b;
    b = a;
    a = t1 + t2;
  }
  h[0] += a, h[1] += b, h[2] += c, h[3] += d, h[4] += e, h[5] += f, h[6] += g, h[7] += k;
}

}  // namespace

std::string Sha256Hex(std::string_view bytes) {
  std::array<uint32_t, 8> h = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                               0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  size_t n = bytes.size(), i = 0;
  for (; i + 64 <= n; i += 64) Compress(h, data + i);
  // Padding: a 1 bit, zeros, and the message length in bits as a 64-bit big-endian number.
  unsigned char tail[128] = {};
  const size_t rest = n - i;
  for (size_t k = 0; k < rest; ++k) tail[k] = data[i + k];
  tail[rest] = 0x80;
  const size_t tail_len = rest + 1 + 8 <= 64 ? 64 : 128;
  const uint64_t bits = uint64_t(n) * 8;
  for (int k = 0; k < 8; ++k) tail[tail_len - 1 - k] = static_cast<unsigned char>(bits >> (8 * k));
  for (size_t k = 0; k < tail_len; k += 64) Compress(h, tail + k);
  std::string hex;
  char buf[9];
  for (uint32_t word : h) {
    std::snprintf(buf, sizeof buf, "%08x", word);
    hex += buf;
  }
  return hex;
}

namespace {

bool EndsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// One number under `key` at `path`.
void CheckValue(const std::string& key, const std::string& path, double v, std::vector<std::string>& out) {
  if (EndsWith(key, "modulus_GPa") && (v < 0.5 || v > 1200))
    out.push_back(path + ": a Young's modulus of " + Num(v) + " GPa is implausible (steel: 206 GPa" +
                  (v > 1e4 ? "; the value looks like MPa" : "") + ")");
  if (EndsWith(key, "modulus_MPa") && (v < 500 || v > 1.2e6))
    out.push_back(path + ": a Young's modulus of " + Num(v) + " MPa is implausible (steel: 206000 MPa" +
                  (v < 1200 ? "; the value looks like GPa" : "") + ")");
  if (key.find("friction_coefficient") != std::string::npos && v > 1)
    out.push_back(path + ": a friction coefficient of " + Num(v) +
                  " is implausible for lubricated rolling contact (above 1)");
  if (EndsWith(key, "_rpm") && v > 1e5)
    out.push_back(path + ": a speed of " + Num(v) + " rpm is implausible for a cam (above 100000 rpm)");
  if (EndsWith(key, "_mm") && key.find("_per_") == std::string::npos && std::abs(v) > 1e4)
    out.push_back(path + ": a length of " + Num(v) + " mm is implausible for a cam mechanism (above 10 m)");
}

void Walk(const nlohmann::json& j, const std::string& key, const std::string& path,
          std::vector<std::string>& out) {
  if (j.is_number() && !j.is_boolean()) CheckValue(key, path, j.get<double>(), out);
  if (j.is_object())
    for (auto it = j.begin(); it != j.end(); ++it) Walk(*it, it.key(), path + "/" + it.key(), out);
  if (j.is_array())  // an array's numbers carry the key of the array ("cam_speeds_rpm": [...])
    for (size_t i = 0; i < j.size(); ++i) Walk(j[i], key, path + "/" + std::to_string(i), out);
}

}  // namespace

std::vector<std::string> PlausibilityWarnings(const nlohmann::json& study) {
  std::vector<std::string> out;
  Walk(study, "", "", out);
  return out;
}

}  // namespace camopt::studies
