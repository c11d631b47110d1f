// The sequence search's terms at one angle for every steady phase at once
// (still_epigraph.h). A sequence's phases share the samples'
// positions and differ only in their weights, so each pair's sign and
// distance, and each angle's sorted order, serve all of them: the SIMD lanes
// run over phases, each lane doing one phase's arithmetic in the one-phase
// code's order (Highway, -ffp-contract=off), so every result has the same
// bits as that code's, on every path, for finite weights.
//
// Values and derivatives are separate calls: the search needs every angle's
// value before it knows how much each angle's derivative counts, and
// computing the derivatives again then is cheaper than keeping them all.
#pragma once

#include <cstddef>
#include <span>

#include "aapat/core/gradient.h"

namespace aapat {

// Phase arrays: for each sample j, `stride` values, phase k's at
// [j * stride + k]. The stride is a multiple of kPhaseLanes (the widest
// vector of doubles), so every path reads whole vectors; lanes past
// `phases` are computed from the arrays' padding and mean nothing.
inline constexpr size_t kPhaseLanes = 8;
inline size_t phase_stride(size_t phases) {
  return (phases + kPhaseLanes - 1) / kPhaseLanes * kPhaseLanes;
}

// One angle's share of each phase's constraint row gradient: phase k's
// derivative d in sample j's projection counts as term = coef[k] * (scale *
// d) where coef[k] != 0, and the row's gradient (the phase arrays gx, gy)
// gains term * nx in x_j and term * ny in y_j, as the row sums its angles.
struct RowShare {
  const double* coef;  // [phase]
  double scale, nx, ny;
  double* gx;
  double* gy;
};

// For each phase k < phases, with w_k column k of the phase array w: e1[k]
// = e1_squared_gradient(half_mean_distance, at, w_k, dp_k, dw_k)'s value;
// e1_squared_derivatives_phases adds dp_k to the row and, unless dw is
// null, writes dw_k (a phase array). The same bits.
void e1_squared_phases(double half_mean_distance, const HeldSamples& at, const double* w,
                       size_t stride, size_t phases, double* e1);
void e1_squared_derivatives_phases(const HeldSamples& at, const double* w, size_t stride,
                                   size_t phases, const RowShare& row, double* dw);

// For each phase, the change of the step response between two frames whose
// samples' weights change by c (a phase array): F = sum_j |R_j| (p_(j+1) -
// p_(j)) over the samples in `order` (sorted by p), R_j the running sum of
// c, so dF/dp_(j) = |R_(j-1)| - |R_j| and dF/dc_(j) = the sum of sign(R_i)
// gap_i over i >= j. f2[k] = F^2; the derivatives add dF^2/dp to the row
// and write dc = dF^2/dc (a phase array).
void flicker_squared_phases(std::span<const double> p, std::span<const size_t> order,
                            const double* c, size_t stride, size_t phases, double* f2);
void flicker_squared_derivatives_phases(std::span<const double> p, std::span<const size_t> order,
                                        const double* c, size_t stride, size_t phases,
                                        const RowShare& row, double* dc);

// Samples sorted by their projection p at one angle, with J(p_i) (j), each
// one's weight within its frame (w) and its frame.
struct SortedSamples {
  std::span<const double> p, j, w;
  std::span<const size_t> frame;
};

// The upscale search's terms at one angle for every steady phase at once
// (still_search.cpp), u and c phase arrays over frames (phase k's at
// [frame * stride + k]): phase k weighs sample i by u[frame_i][k] w_i, and
// e1[k] is e1_squared_in_order of those weights (J at p_i from j); it
// changes sample i's weight by c[frame_i][k] w_i from the phase before,
// and f[k] is the flicker sweep's F = sum_i |R_i| (p_(i+1) - p_i), R_i the
// running change (not squared). The same bits as those loops, phase by phase.
void sorted_terms_phases(double half_mean_distance, const SortedSamples& s, const double* u,
                         const double* c, size_t stride, size_t phases, double* e1, double* f);

}  // namespace aapat
