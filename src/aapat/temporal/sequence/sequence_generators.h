// Jitter sequences as engines make them, and sequences made from patterns.
//
// Jitter (each frame one sample, P(1,1,1), offsets in [-1/2, 1/2)):
//   halton:b1=2,b2=3,frames=8,start=1   Halton with any two bases; start = 1
//                                       skips index 0 (the pixel corner), as
//                                       FSR 2, DLSS and XeSS integrations do
//   bevy-halton:frames=8                the pixel centre, then Halton(2,3)
//                                       from index 1 (Bevy 0.17)
//   r2:frames=16,start=1                Roberts' R2 (the plastic number g:
//                                       n/g, n/g^2 mod 1, from 1/2)
//   sobol:frames=16,seed=1              the first two Sobol dimensions,
//                                       Owen-scrambled (nested uniform) by seed
//   random:frames=16,seed=1             white noise: each frame uniform
//   display-lattice:ratio=1.5           the offsets where display pixel
//                                       centres fall in a render pixel, in a
//                                       Latin order (n^2 frames by default)
// From a pattern of n samples (one pixel):
//   split:frames=K                      K frames of n/K samples each, sample i
//                                       in frame i mod K (any pattern file;
//                                       alternating MSAA)
//   rooks-order, blue-noise-order       n one-sample frames, the samples
//                                       ordered so that every prefix is as
//                                       stratified per axis / as spread out
//                                       (farthest point first) as it can be
//   msaa-alternating:samples=2,frames=2 the standard MSAA pattern of
//                                       samples x frames split in turn
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "aapat/core/spec.h"
#include "aapat/temporal/sequence/render_scale.h"
#include "aapat/temporal/sequence/sequence.h"

namespace aapat {

// The plastic number g, the real root of x^3 = x + 1: R2 steps by (1/g, 1/g^2).
inline constexpr double kPlasticNumber = 1.32471795724474602596;

// The radical inverse of i in base b (the Halton coordinate), in [0, 1).
double radical_inverse_of(uint64_t i, int base);

// `pattern` is what split, rooks-order and blue-noise-order take apart (a
// one-pixel pattern); the others ignore it. Throws Error naming the problem.
using SequenceRegistry = Registry<Sequence, const std::optional<Pattern>&>;
const SequenceRegistry& sequence_registry();
Sequence make_sequence(std::string_view spec, const std::optional<Pattern>& pattern = {});

}  // namespace aapat
