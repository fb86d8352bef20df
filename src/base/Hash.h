// FNV-1a 64 over bytes: the one hash behind determinism checks (radiosity, image) and the
// checkpoint checksum. Hashes bytes in memory order, so a float's bit pattern hashes the same
// on every little-endian machine hemirad runs on.
#pragma once
#include <cstddef>
#include <cstdint>

namespace hemirad {

class Fnv1a {
 public:
  void add(const void* data, std::size_t n) {
    auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h_ = (h_ ^ p[i]) * 1099511628211ull;
  }
  template <class T>
  void add(const T& v) {
    add(&v, sizeof v);
  }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 1469598103934665603ull;
};

}  // namespace hemirad
