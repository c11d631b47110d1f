// Parity of the fsr2 preset's per-pixel arithmetic with FSR 2.2's shaders:
// an independent transcription below, written from FidelityFX-FSR2 v2.2.1
// (src/ffx-fsr2-api/shaders/, file:line on each step) in the shader's own
// variables and coordinates (pixel centres at +0.5, uv in [0, 1], the API's
// jitter), against the library's fsr2_gather, fsr2_history_sample and
// fsr2_accumulate (centres at integers, the sample placed at minus the
// jitter) on small hand-made frames, every pixel including the borders.
#include "aapat/temporal/engine/fsr2_accumulate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace aapat {
namespace {

using F3 = std::array<double, 3>;
using F4 = std::array<double, 4>;
constexpr double kPiShader = 3.141592653589793;
constexpr double FSR2_EPSILON = 1e-3;  // ffx_fsr2_common.h:34

double ffxLerp(double x, double y, double t) {
  return x + (y - x) * t;
}
double ffxSaturate(double x) {
  return std::min(1.0, std::max(0.0, x));
}

// ffx_fsr2_common.h:268-276
F3 RGBToYCoCg(F3 c) {
  return {0.25 * c[0] + 0.5 * c[1] + 0.25 * c[2], 0.5 * c[0] - 0.5 * c[2],
          -0.25 * c[0] + 0.5 * c[1] - 0.25 * c[2]};
}
// ffx_fsr2_common.h:243-250
F3 YCoCgToRGB(F3 c) {
  return {c[0] + c[1] - c[2], c[0] + c[2], c[0] - c[1] - c[2]};
}

// ffx_fsr2_sample.h:157-177 (the FSR 1 approximation, upsampling's default type 2,
// ffx_fsr2_upsample.h:38-50)
double Lanczos2ApproxSq(double x2) {
  x2 = std::min(x2, 4.0);
  const double a = (2.0 / 5.0) * x2 - 1, b = (1.0 / 4.0) * x2 - 1;
  return ((25.0 / 16.0) * a * a - (25.0 / 16.0 - 1)) * (b * b);
}
// ffx_fsr2_sample.h:127-137 (the reference type, reprojection's default,
// ffx_fsr2_reproject.h:25-27)
double Lanczos2(double x) {
  x = std::min(std::abs(x), 2.0);
  return std::abs(x) < FSR2_EPSILON ? 1.0
                                    : (std::sin(kPiShader * x) / (kPiShader * x)) *
                                          (std::sin(0.5 * kPiShader * x) / (0.5 * kPiShader * x));
}

struct Textures {
  int renderW, renderH, displayW, displayH;
  std::vector<F3> input;    // the render frame, RGB
  std::vector<F4> history;  // r_internal_upscaled_color: RGB and the temporal reactive factor
  F3 input_at(int x, int y) const {  // an out-of-range load gives 0
    if (x < 0 || y < 0 || x >= renderW || y >= renderH) return {0, 0, 0};
    return input[static_cast<size_t>(y * renderW + x)];
  }
  F4 history_at(int x, int y) const { return history[static_cast<size_t>(y * displayW + x)]; }
};

// ffx_fsr2_sample.h:494-502 ClampCoord
int ClampCoord(int sample, int offset, int size) {
  int r = sample + offset;
  if (offset < 0) r = std::max(r, 0);
  if (offset > 0) r = std::min(r, size - 1);
  return r;
}

// ffx_fsr2_sample.h:569-581 DeclareCustomTextureSample with 516-540 (the 4x4
// fetch) and 242-283 (Lanczos2 rows and columns, then deringing by the
// inner 2x2).
F4 HistorySample(const Textures& t, double u, double v) {
  double px = u * t.displayW - 0.5, py = v * t.displayH - 0.5;
  px = std::max(0.0, std::min(double(t.displayW), px));
  py = std::max(0.0, std::min(double(t.displayH), py));
  const int ix = static_cast<int>(std::floor(px)), iy = static_cast<int>(std::floor(py));
  const double fx = px - std::floor(px), fy = py - std::floor(py);
  F4 c[4][4];  // c[x][y], fColorXY at offsets -1..+2
  // (An offset of 0 is not clamped: past the last texel only for a point
  // off the image, which the caller never samples; kept in range here.)
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      c[a][b] = t.history_at(std::min(ClampCoord(ix, a - 1, t.displayW), t.displayW - 1),
                             std::min(ClampCoord(iy, b - 1, t.displayH), t.displayH - 1));
  auto row = [](const F4& c0, const F4& c1, const F4& c2, const F4& c3, double tt) {
    const double w0 = Lanczos2(-1.0 - tt), w1 = Lanczos2(-0.0 - tt), w2 = Lanczos2(+1.0 - tt),
                 w3 = Lanczos2(+2.0 - tt);
    F4 r;
    for (size_t k = 0; k < 4; ++k)
      r[k] = (w0 * c0[k] + w1 * c1[k] + w2 * c2[k] + w3 * c3[k]) / (w0 + w1 + w2 + w3);
    return r;
  };
  F4 x[4];
  for (int b = 0; b < 4; ++b) x[b] = row(c[0][b], c[1][b], c[2][b], c[3][b], fx);
  F4 xy = row(x[0], x[1], x[2], x[3], fy);
  for (size_t k = 0; k < 4; ++k) {
    const double lo = std::min({c[1][1][k], c[2][1][k], c[1][2][k], c[2][2][k]}),
                 hi = std::max({c[1][1][k], c[2][1][k], c[1][2][k], c[2][2][k]});
    xy[k] = std::min(hi, std::max(lo, xy[k]));
  }
  return xy;
}

struct Box {  // ffx_fsr2_common.h:106-113
  F3 boxCenter{}, boxVec{}, aabbMin{}, aabbMax{};
  double fBoxCenterWeight = 0;
};

// Accumulate(iPxHrPos), ffx_fsr2_accumulate.h:239-293, without locks, luma
// instability (its factor is 0 without locks' history), reactive masks and
// depth clip; exposure 1. Returns the stored history texel.
F4 ShaderAccumulate(const Textures& t, int hx, int hy, double jitterX, double jitterY, double mvX,
                    double mvY, bool resetFrame) {
  const double dsX = double(t.renderW) / t.displayW, dsY = double(t.renderH) / t.displayH;
  // InitParams, accumulate.h:211-237
  const double hrU = (hx + 0.5) / t.displayW, hrV = (hy + 0.5) / t.displayH;
  const double hrVelocity = std::hypot(mvX * t.displayW, mvY * t.displayH);  // :25-28
  const double repU = hrU + mvX, repV = hrV + mvY;                           // reproject.h:101
  const bool existing = repU >= 0 && repU <= 1 && repV >= 0 && repV <= 1;    // reproject.h:94-97
  const bool isNew = !existing || resetFrame;
  // accumulate.h:243-255
  F3 history{0, 0, 0};
  double temporalReactive = 0;
  bool inMotionLastFrame = false;
  if (existing && !resetFrame) {  // ReprojectHistoryColor, reproject.h:106-117
    const F4 h = HistorySample(t, repU, repV);
    history = RGBToYCoCg({h[0], h[1], h[2]});
    temporalReactive = ffxSaturate(std::abs(h[3]));
    inMotionLastFrame = h[3] < 0;
  }
  const double thisFrameReactive = std::max(0.0, temporalReactive);
  // ComputeUpsampledColorAndWeight, upsample.h:85-192
  const double dstX = hx + 0.5, dstY = hy + 0.5;      // :92
  const double srcX = dstX * dsX, srcY = dstY * dsY;  // :93
  const int inX = static_cast<int>(std::floor(srcX)),
            inY = static_cast<int>(std::floor(srcY));                             // :94
  const double unjX = (inX + 0.5) - jitterX, unjY = (inY + 0.5) - jitterY;        // :102
  const int tlX = unjX > srcX ? -2 : -1, tlY = unjY > srcY ? -2 : -1;             // :104-106
  const bool flipRow = unjY > srcY, flipCol = unjX > srcX;                        // :112-113
  const double baseX = unjX - srcX, baseY = unjY - srcY;                          // :135
  const double kernelReactive = std::max(thisFrameReactive, isNew ? 1.0 : 0.0);   // :138
  const double maxKernel = std::min(1.99, 1 + (1 / dsX - 1) * 1.0);               // :77-83
  const double biasMax = maxKernel * (1 - kernelReactive);                        // :139
  const double biasMin = std::max(1.0, (1 + biasMax) * 0.3);                      // :141
  const double biasFactor = std::max(0.0, std::max(0.25 * 0.0, kernelReactive));  // :142
  const double kernelBias = ffxLerp(biasMax, biasMin, biasFactor);                // :143
  const double curveBias = ffxLerp(-2.0, -3.0, ffxSaturate(hrVelocity / 50));     // :145
  double sum[3] = {0, 0, 0}, weight = 0;
  Box box;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) {
      const int cx = flipCol ? 3 - col : col, cy = flipRow ? 3 - row : row;  // :153
      const double offX = baseX + tlX + cx, offY = baseY + tlY + cy;         // :154-155
      const int sx = inX + tlX + cx, sy = inY + tlY + cy;                    // :157
      const F3 sample = RGBToYCoCg(t.input_at(sx, sy));  // depth_clip.h:206-217, :127-129
      const bool onScreen = sx >= 0 && sy >= 0 && sx < t.renderW && sy < t.renderH;   // :159
      const double bx = offX * kernelBias, by = offY * kernelBias;                    // :44
      const double w = (onScreen ? 1.0 : 0.0) * Lanczos2ApproxSq(bx * bx + by * by);  // :160
      for (size_t k = 0; k < 3; ++k) sum[k] += sample[k] * w;                         // :162
      weight += w;
      const double boxWeight = std::exp(curveBias * (offX * offX + offY * offY));  // :166-167
      const bool initial = row == 0 && col == 0;                                   // :169
      for (size_t k = 0; k < 3; ++k) {  // common.h:146-168 RectificationBoxAddSample
        const double ws = sample[k] * boxWeight;
        box.aabbMin[k] = initial ? sample[k] : std::min(box.aabbMin[k], sample[k]);
        box.aabbMax[k] = initial ? sample[k] : std::max(box.aabbMax[k], sample[k]);
        box.boxCenter[k] = initial ? ws : box.boxCenter[k] + ws;
        box.boxVec[k] = initial ? sample[k] * ws : box.boxVec[k] + sample[k] * ws;
      }
      box.fBoxCenterWeight = initial ? boxWeight : box.fBoxCenterWeight + boxWeight;
    }
  // RectificationBoxComputeVarianceBoxData, common.h:199-206
  box.fBoxCenterWeight = std::abs(box.fBoxCenterWeight) > FSR2_EPSILON ? box.fBoxCenterWeight : 1;
  for (size_t k = 0; k < 3; ++k) {
    box.boxCenter[k] /= box.fBoxCenterWeight;
    box.boxVec[k] /= box.fBoxCenterWeight;
    box.boxVec[k] = std::sqrt(std::abs(box.boxVec[k] - box.boxCenter[k] * box.boxCenter[k]));
  }
  weight *= weight > FSR2_EPSILON ? 1.0 : 0.0;  // :177
  F3 upsampled{sum[0], sum[1], sum[2]};
  if (weight > FSR2_EPSILON) {  // :179-185, Deringing :27-30
    for (size_t k = 0; k < 3; ++k)
      upsampled[k] = std::min(box.aabbMax[k], std::max(box.aabbMin[k], upsampled[k] / weight));
    weight *= 1.0 / 12.0;  // fUpsampleLanczosWeightScale, common.h:50
  }
  // ComputeBaseAccumulationWeight, accumulate.h:124-134 (fMaxAccumulationLanczosWeight 1)
  double accumulation = 1.0 * (existing ? 1.0 : 0.0) * (1 - thisFrameReactive) * (1 - 0.0);
  accumulation = std::min(
      accumulation, ffxLerp(accumulation, weight * 10,
                            std::max(inMotionLastFrame ? 1.0 : 0.0, ffxSaturate(hrVelocity * 10))));
  accumulation =
      std::min(accumulation, ffxLerp(accumulation, weight, ffxSaturate(hrVelocity / 20)));
  F3 out;
  if (isNew) {  // :270-272
    out = YCoCgToRGB(upsampled);
  } else {
    // RectifyHistory, accumulate.h:57-98
    const double scaleInfluence = std::min(20.0, std::pow(1.0 / std::abs(dsX * dsY), 3.0));  // :66
    const double boxScaleT = std::max(0.0, std::max(0.0, ffxSaturate(hrVelocity / 20)));  // :68-69
    const double boxScale = ffxLerp(scaleInfluence, 1.0, boxScaleT);                      // :70
    F3 lo, hi;
    bool outside = false;
    for (size_t k = 0; k < 3; ++k) {
      lo[k] = std::max(box.aabbMin[k], box.boxCenter[k] - box.boxVec[k] * boxScale);  // :72-78
      hi[k] = std::min(box.aabbMax[k], box.boxCenter[k] + box.boxVec[k] * boxScale);  // :79
      outside = outside || lo[k] > history[k] || history[k] > hi[k];                  // :81
    }
    if (outside) {
      const double contribution = std::max(0.0, 0.0) * (1 - std::pow(0.0, 0.5));  // :85-89
      for (size_t k = 0; k < 3; ++k) {
        const double clamped = std::min(hi[k], std::max(lo[k], history[k]));   // :83
        history[k] = ffxLerp(clamped, history[k], ffxSaturate(contribution));  // :92
      }
      accumulation =
          ffxLerp(std::min(accumulation, 0.1), accumulation, ffxSaturate(contribution));  // :95-96
    }
    // Accumulate, accumulate.h:36-55
    const double total = std::max(FSR2_EPSILON, accumulation + weight);
    const double alpha = weight / total;
    for (size_t k = 0; k < 3; ++k) history[k] = ffxLerp(history[k], upsampled[k], alpha);
    out = YCoCgToRGB(history);
  }
  // ComputeTemporalReactiveFactor, accumulate.h:193-209
  double f = std::min(0.99, thisFrameReactive);
  f = std::max(f, ffxLerp(f, 0.4, ffxSaturate(hrVelocity)));
  f = std::max(f * f, std::max(0.0 * 0.1, 0.0));
  f = isNew ? 1.0 : f;
  if (ffxSaturate(hrVelocity * 10) >= 1) f = std::max(FSR2_EPSILON, f) * -1;
  return {out[0], out[1], out[2], f};
}

TEST(Fsr2Accumulate, EveryPixelIsTheShadersArithmetic) {
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> u01(0, 1), half(-0.5, 0.5);
  int compared = 0;
  for (const double ratio : {1.0, 1.5, 2.0, 3.0}) {
    Textures t;
    t.displayW = 12;
    t.displayH = 6;
    t.renderW = static_cast<int>(std::lround(t.displayW / ratio));
    t.renderH = static_cast<int>(std::lround(t.displayH / ratio));
    ASSERT_DOUBLE_EQ(double(t.displayW) / t.renderW, ratio);
    ASSERT_DOUBLE_EQ(double(t.displayH) / t.renderH, ratio);
    const double used = ratio;
    for (int trial = 0; trial < 6; ++trial) {
      t.input.assign(static_cast<size_t>(t.renderW * t.renderH), {});
      for (F3& c : t.input) c = {u01(rng), u01(rng), u01(rng)};
      t.history.assign(static_cast<size_t>(t.displayW * t.displayH), {});
      for (F4& c : t.history) c = {u01(rng), u01(rng), u01(rng), 2 * u01(rng) - 1};
      const double jx = half(rng), jy = half(rng);
      // Motion in display pixels: at rest, slow, the 0.1 px threshold, fast, past 20 px.
      const std::array<double, 5> speeds{0.0, 0.04, 0.3, 3.0, 25.0};
      const double speed = speeds[static_cast<size_t>(trial % 5)], angle = 6.283 * u01(rng);
      const double mx = speed * std::cos(angle), my = speed * std::sin(angle);
      const bool reset = trial == 5;
      std::vector<double> frame;
      for (const F3& c : t.input) frame.insert(frame.end(), c.begin(), c.end());
      Plane history{t.displayW, t.displayH, 4, {}};
      for (const F4& c : t.history) history.values.insert(history.values.end(), c.begin(), c.end());
      for (int y = 0; y < t.displayH; ++y)
        for (int x = 0; x < t.displayW; ++x) {
          const F4 want =
              ShaderAccumulate(t, x, y, jx, jy, mx / t.displayW, my / t.displayH, reset);
          // The library: the sample placed at minus the API's jitter.
          const Fsr2Samples in =
              fsr2_gather({t.renderW, t.renderH, 3, frame.data()}, x, y, {-jx, -jy}, used);
          const Vec2 q{x + mx, y + my};
          const bool valid = !reset && q.x >= -0.5 && q.x <= t.displayW - 0.5 && q.y >= -0.5 &&
                             q.y <= t.displayH - 0.5;
          Fsr2Pixel previous;
          if (valid) previous = fsr2_history_sample(history, q);
          const Fsr2Pixel got =
              fsr2_accumulate(in, valid ? &previous : nullptr, used, std::hypot(mx, my));
          for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(got.rgb[k], want[k], 1e-12) << x << "," << y;
          EXPECT_NEAR(got.reactive, want[3], 1e-12) << x << "," << y;
          ++compared;
        }
    }
  }
  EXPECT_EQ(compared, 4 * 6 * 72);
}

TEST(Fsr2Accumulate, SteadyStateNumbersOfTheShaders) {
  // The kernel is in display pixels at steady state: bias min(1.99, R).
  EXPECT_DOUBLE_EQ(fsr2_kernel_bias(1.5, 0), 1.5);
  EXPECT_DOUBLE_EQ(fsr2_kernel_bias(3, 0), 1.99);
  // A new sample: bias max(1, 0.3) lerped fully to it, 1 (render pixels).
  EXPECT_DOUBLE_EQ(fsr2_kernel_bias(2, 1), 1);
  // FSR 1's approximation: 1 at 0, 0 at 1 and at 2 (the zeros of Lanczos-2).
  EXPECT_DOUBLE_EQ(fsr2_lanczos2_approx_sq(0), 1);
  EXPECT_NEAR(fsr2_lanczos2_approx_sq(1), 0, 1e-15);
  EXPECT_NEAR(fsr2_lanczos2_approx_sq(4), 0, 1e-15);
  // In motion after a frame of motion, the accumulation is at most 10 w,
  // lowered toward w by v / 20: alpha = w / (accumulation + w).
  Fsr2Samples flat;
  for (size_t k = 0; k < 9; ++k) {
    flat.offset[k] = {double(k % 3) - 1.1, double(k / 3) - 0.9};
    flat.ycocg[k] = {0.25, 0, 0};
    flat.on_screen[k] = true;
  }
  const Fsr2Pixel moving{{0.75, 0.75, 0.75}, -0.005};
  Fsr2Samples dark = flat;
  for (auto& c : dark.ycocg) c = {0.5, 0, 0};
  // The history (0.75) is outside the box of a flat 0.5 frame: clamped to it.
  EXPECT_NEAR(fsr2_accumulate(dark, &moving, 1.5, 0.5).rgb[0], 0.5, 1e-12);
  // Inside a box that holds it: the blend alone, alpha = 1/11.
  for (size_t k = 0; k < 9; ++k) dark.ycocg[k] = {k % 2 ? 0.5 : 0.75, 0, 0};
  const Fsr2Upsampled up = fsr2_upsample(dark, 1.5, 0.005, 0.5);
  double accumulation = std::min(1 - 0.005, 10 * up.weight);
  accumulation += (up.weight - accumulation) * 0.5 / 20;
  const double alpha = up.weight / (accumulation + up.weight);
  const Fsr2Pixel got = fsr2_accumulate(dark, &moving, 1.5, 0.5);
  EXPECT_NEAR(got.rgb[0], 0.75 + (up.ycocg[0] - 0.75) * alpha, 1e-12);
  EXPECT_GT(alpha, 1.0 / 11.5);  // about 0.09 at 0.1 to 2 px per frame, not FSR 2.1's 0.2
  EXPECT_LT(alpha, 1.0 / 10);
  // The factor it keeps: min(0.99, 0.005) pulled toward 0.4 by half, squared, negative.
  EXPECT_NEAR(got.reactive, -std::pow(0.005 + (0.4 - 0.005) * 0.5, 2), 1e-15);
}

}  // namespace
}  // namespace aapat
