#pragma once
// Integer mixing for the open-addressing tables in this folder. The tables hash small integers
// (vertex ids, float bit patterns) that are highly regular, so the mix must spread every input
// bit over the high bits that pick the bucket.
#include <bit>
#include <cstddef>
#include <cstdint>

namespace bz::geo::detail {

inline std::uint64_t mix64(std::uint64_t x) {
    x ^= x >> 32;
    x *= 0xd6e8feb86659fd93ull;
    x ^= x >> 32;
    x *= 0xd6e8feb86659fd93ull;
    x ^= x >> 32;
    return x;
}

inline std::uint64_t hash3(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const std::uint64_t ab = (std::uint64_t{a} << 32) | b;
    return mix64(ab ^ (std::uint64_t{c} * 0x9e3779b97f4a7c15ull));
}

// Power-of-two table size with load factor at most 1/2, so probe chains stay short.
inline std::size_t table_size_for(std::size_t items) {
    return std::bit_ceil(items * 2 + 16);
}

}  // namespace bz::geo::detail
