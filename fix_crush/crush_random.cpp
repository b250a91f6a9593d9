/* Crushing model (plain C++): counter-based random numbers (see crush_random.h). */
#include "crush_random.h"

namespace crush {

static std::uint64_t splitmix64(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::uint64_t hash_draw(std::uint64_t seed, std::uint64_t tag, Stream stream, std::uint64_t counter)
{
  std::uint64_t h = splitmix64(seed);
  h = splitmix64(h ^ tag);
  h = splitmix64(h ^ static_cast<std::uint64_t>(stream));
  return splitmix64(h ^ counter);
}

double uniform_open(std::uint64_t seed, std::uint64_t tag, Stream stream, std::uint64_t counter)
{
  // 53 random bits, shifted by half a unit: never exactly 0 or 1.
  const std::uint64_t bits = hash_draw(seed, tag, stream, counter) >> 11;
  return (static_cast<double>(bits) + 0.5) * 1.1102230246251565404e-16;  // 2^-53
}

}  // namespace crush
