#pragma once

#include <cstddef>
#include <vector>

#include "aapat/core/filter.h"
#include "aapat/render/scene.h"

namespace aapat {

// What one pixel's samples give the output pixels around it under a
// separable filter: for output pixel (a + di, b + dj), |di|, |dj| <= reach,
// the weight W = sum_s h(x_s - (a + di) - offset) h(y_s - (b + dj) - offset)
// and, per channel, S = sum_s of that weight times the sample's value.
//
// A reference weighs about 10^3 samples per pixel into 25 output pixels:
// sums over the pixel's samples, as 25 dot products over arrays of filter
// values, run on vector lanes where one sample at a time into 25 output
// pixels ran on memory. Each sum runs in four interleaved chains (sample s
// in chain s mod 4) joined as (c0 + c1) + (c2 + c3): the same bits on every
// SIMD path (one vector of four lanes, two of two or four of one).
class PixelSplat {
 public:
  static constexpr size_t kChains = 4;

  PixelSplat(const Filter& filter, int reach, double offset, int channels);

  void clear() { count_ = 0; }
  void add(double x, double y, const Rgb& value) {
    if (count_ + kChains > x_.size()) grow();  // room for the padding too
    x_[count_] = x;
    y_[count_] = y;
    for (size_t c = 0; c < static_cast<size_t>(channels_); ++c)
      values_[c * x_.size() + count_] = value[c];
    ++count_;
  }
  // The sums of the samples added since clear(), all of them pixel (a, b)'s.
  void weigh(int a, int b);

  int reach() const { return reach_; }
  double weight(int di, int dj) const { return weight_[cell(di, dj)]; }
  double sum(int di, int dj, int channel) const {
    return sum_[cell(di, dj) * static_cast<size_t>(channels_) + static_cast<size_t>(channel)];
  }

 private:
  void grow();
  size_t cell(int di, int dj) const {
    return static_cast<size_t>(dj + reach_) * static_cast<size_t>(side_) +
           static_cast<size_t>(di + reach_);
  }

  const Filter& filter_;
  int reach_, side_, channels_;
  double offset_;
  size_t count_ = 0;
  // Samples as columns (padded with zero values to a multiple of 4) and the
  // filter's values for each output column and row.
  std::vector<double> x_, y_, values_, hx_, hy_;
  std::vector<double> weight_, sum_;
};

}  // namespace aapat
