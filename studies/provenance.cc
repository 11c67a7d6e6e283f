#include "studies/provenance.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include <nettle/sha2.h>

#include "studies/backend_input.h"

#ifndef CAMOPT_VERSION_STRING
#error "CAMOPT_VERSION_STRING is set by cmake/camopt_schemas.cmake"
#endif

namespace camopt::studies {

std::string CamoptVersion() { return CAMOPT_VERSION_STRING; }

std::string Sha256Hex(std::string_view bytes) {
  // Nettle's SHA-256 (FIPS 180-4; Debian's nettle-dev).
  sha256_ctx ctx;
  sha256_init(&ctx);
  sha256_update(&ctx, bytes.size(), reinterpret_cast<const uint8_t*>(bytes.data()));
  std::array<uint8_t, SHA256_DIGEST_SIZE> digest{};
  sha256_digest(&ctx, digest.size(), digest.data());
  std::string hex;
  char buf[3];
  for (uint8_t byte : digest) {
    std::snprintf(buf, sizeof buf, "%02x", byte);
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
  if (j.is_string() && key == "backend")
    if (auto w = BackendSpellingWarning(j.get<std::string>(), path)) out.push_back(*w);
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
