#pragma once
// FNV-1a, 64-bit: stable across runs and machines, used for state hashes and file hashes.
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

namespace bz {

class Hasher {
  public:
    void bytes(const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < n; ++i) {
            h_ ^= p[i];
            h_ *= 0x100000001b3ull;
        }
    }
    template <class T>
    void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&v, sizeof(T));
    }
    void text(std::string_view s) {
        value(s.size());
        bytes(s.data(), s.size());
    }
    std::uint64_t digest() const { return h_; }

  private:
    std::uint64_t h_ = 0xcbf29ce484222325ull;
};

inline std::uint64_t hash_bytes(std::string_view s) {
    Hasher h;
    h.bytes(s.data(), s.size());
    return h.digest();
}

// A hash as the files that record it write it: 16 lower-case hex digits.
inline std::string hex(std::uint64_t v) {
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016" PRIx64, v);
    return buf;
}

}  // namespace bz
