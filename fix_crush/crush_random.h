/* Crushing model (plain C++): counter-based random numbers.

   Every random quantity of the model (a particle's strength, an event's fragment orientation) is a
   pure function of (seed, particle tag, stream, counter): no generator state is carried between
   events, so the result never depends on the processor count, the domain decomposition or the order
   in which events are processed. The mixing function is SplitMix64's finaliser (Steele, Lea & Flood,
   "Fast splittable pseudorandom number generators", OOPSLA 2014), applied to a chained hash of the
   four integers. */
#ifndef CRUSH_RANDOM_H
#define CRUSH_RANDOM_H

#include <cstdint>

namespace crush {

// Independent streams of the model, so that strength and orientation draws never coincide.
enum class Stream : std::uint64_t { strength = 1, orientation = 2 };

// A 64-bit hash of (seed, tag, stream, counter), uniformly distributed over all 64-bit values.
std::uint64_t hash_draw(std::uint64_t seed, std::uint64_t tag, Stream stream, std::uint64_t counter);

// A uniform double in the open interval (0, 1) from the same four integers.
double uniform_open(std::uint64_t seed, std::uint64_t tag, Stream stream, std::uint64_t counter);

}  // namespace crush

#endif
