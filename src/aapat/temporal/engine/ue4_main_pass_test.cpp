// Parity of the ue4 preset's per-pixel arithmetic with Unreal Engine's main
// TAA pass: an independent transcription below, written from the 4.26-era
// TemporalAA.cpp (SetupSampleWeightParameters; AddTemporalAAPass's history
// parameters) and TemporalAA.usf's main pass (TAA_PASS_CONFIG 0, its
// functions named on each step) with GetBicubic2DCatmullRomSamples, in the
// shader's own variables and coordinates (ViewportUV, ScreenPos in [-1, 1]
// with y up, buffer UVs, the API's TemporalJitterPixels), against the
// library's ue4_plus_weights, ue4_gather, ue4_history_sample and
// ue4_main_pass (centres at integers, the sample placed at minus the jitter)
// on small hand-made frames, every pixel including the borders.
#include "aapat/temporal/engine/ue4_main_pass.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "testing/gpu_texture.h"

namespace aapat {
// Named, not anonymous: the unity build puts FSR 2's transcription, which
// has its own RGBToYCoCg and Textures, in the same translation unit.
namespace ue4_shader {

using F2 = std::array<double, 2>;
using F3 = std::array<double, 3>;

// HLSL's saturate: NaN to 0 (D3D), +inf to 1.
double saturate(double x) {
  return std::isnan(x) ? 0.0 : std::min(1.0, std::max(0.0, x));
}
double lerp(double a, double b, double t) {
  return a + (b - a) * t;
}

// TemporalAA.usf RGBToYCoCg, YCoCgToRGB, HdrWeightY, WeightedLerpFactors.
F3 RGBToYCoCg(F3 RGB) {
  return {RGB[0] + 2 * RGB[1] + RGB[2], 2 * RGB[0] - 2 * RGB[2], -RGB[0] + 2 * RGB[1] - RGB[2]};
}
F3 YCoCgToRGB(F3 YCoCg) {
  const double Y = YCoCg[0] * 0.25, Co = YCoCg[1] * 0.25, Cg = YCoCg[2] * 0.25;
  return {Y + Co - Cg, Y + Cg, Y - Co - Cg};
}
double HdrWeightY(double Color, double Exposure) {
  return 1 / (Color * Exposure + 4.0);
}
F2 WeightedLerpFactors(double WeightA, double WeightB, double Blend) {
  double BlendA = (1.0 - Blend) * WeightA, BlendB = Blend * WeightB;
  const double RcpBlend = 1 / (BlendA + BlendB);
  return {BlendA * RcpBlend, BlendB * RcpBlend};
}

// TemporalAA.cpp SetupSampleWeightParameters, r.TemporalAAFilterSize 1,
// r.TemporalAACatmullRom 0 (the Gaussian branch).
struct SampleWeightParameters {
  std::array<double, 9> SampleWeights{};
  std::array<double, 5> PlusWeights{};
};
SampleWeightParameters SetupSampleWeightParameters(F2 TemporalJitterPixels) {
  static const double SampleOffsets[9][2] = {{-1, -1}, {0, -1}, {1, -1}, {-1, 0}, {0, 0},
                                             {1, 0},   {-1, 1}, {0, 1},  {1, 1}};
  const double FilterSize = 1;
  SampleWeightParameters P;
  double TotalWeight = 0;
  for (int i = 0; i < 9; i++) {
    const double PixelOffsetX = (SampleOffsets[i][0] - TemporalJitterPixels[0]) / FilterSize;
    const double PixelOffsetY = (SampleOffsets[i][1] - TemporalJitterPixels[1]) / FilterSize;
    // Normal distribution, Sigma = 0.47
    P.SampleWeights[static_cast<size_t>(i)] =
        std::exp(-2.29 * (PixelOffsetX * PixelOffsetX + PixelOffsetY * PixelOffsetY));
    TotalWeight += P.SampleWeights[static_cast<size_t>(i)];
  }
  for (double& w : P.SampleWeights) w /= TotalWeight;
  const auto& S = P.SampleWeights;
  P.PlusWeights = {S[1], S[3], S[4], S[5], S[7]};
  const double TotalWeightPlus = S[1] + S[3] + S[4] + S[5] + S[7];
  for (double& w : P.PlusWeights) w /= TotalWeightPlus;
  return P;
}

// The input scene colour and the history buffer, both W x H RGB (the
// viewport is the whole buffer, read with clamp addressing), and each
// pixel's point a frame earlier.
struct Textures {
  int W = 0, H = 0;
  testing::GpuTexture<F3> InputSceneColor, HistoryBuffer;
  std::vector<F2> Previous;  // pixel units, the scene's exact motion
};

// Common.ush Bicubic2DCatmullRom and GetBicubic2DCatmullRomSamples.
struct FCatmullRomSamples {
  std::array<std::array<int, 2>, 5> UVDir{};
  std::array<F2, 5> UV{};
  std::array<double, 5> Weight{};
  double FinalMultiplier = 1;
};
FCatmullRomSamples GetBicubic2DCatmullRomSamples(F2 UV, F2 Size, F2 InvSize) {
  F2 Sample[3], Weight[3];
  for (size_t a = 0; a < 2; ++a) {
    const double uv = UV[a] * Size[a];
    const double tc = std::floor(uv - 0.5) + 0.5;
    const double f = uv - tc, f2 = f * f, f3 = f2 * f;
    const double w0 = f2 - 0.5 * (f3 + f), w1 = 1.5 * f3 - 2.5 * f2 + 1, w3 = 0.5 * (f3 - f2);
    const double w2 = 1 - w0 - w1 - w3;
    Weight[0][a] = w0;
    Weight[1][a] = w1 + w2;
    Weight[2][a] = w3;
    Sample[0][a] = (tc - 1) * InvSize[a];
    Sample[1][a] = (tc + w2 / Weight[1][a]) * InvSize[a];
    Sample[2][a] = (tc + 2) * InvSize[a];
  }
  FCatmullRomSamples S;
  S.UV = {F2{Sample[1][0], Sample[0][1]}, F2{Sample[0][0], Sample[1][1]},
          F2{Sample[1][0], Sample[1][1]}, F2{Sample[2][0], Sample[1][1]},
          F2{Sample[1][0], Sample[2][1]}};
  S.Weight = {Weight[1][0] * Weight[0][1], Weight[0][0] * Weight[1][1], Weight[1][0] * Weight[1][1],
              Weight[2][0] * Weight[1][1], Weight[1][0] * Weight[2][1]};
  S.UVDir = {{{0, -1}, {-1, 0}, {0, 0}, {1, 0}, {0, 1}}};
  // Reweight after removing the corners
  double CornerWeights = 0;
  for (const double w : S.Weight) CornerWeights += w;
  S.FinalMultiplier = 1 / CornerWeights;
  return S;
}

// TemporalAA.usf SampleHistory (AA_BICUBIC, AA_MANUALLY_CLAMP_HISTORY_UV),
// with TemporalAA.cpp's ScreenPosToHistoryBufferUV and HistoryBufferUVMinMax
// for a history whose viewport is its whole buffer.
F3 SampleHistory(const Textures& T, F2 HistoryScreenPosition) {
  const F2 Size{double(T.W), double(T.H)}, InvSize{1.0 / T.W, 1.0 / T.H};
  const std::array<double, 4> ScreenPosToHistoryBufferUV = {T.W * 0.5 / T.W, -T.H * 0.5 / T.H,
                                                            T.W * 0.5 / T.W, T.H * 0.5 / T.H};
  const std::array<double, 4> HistoryBufferUVMinMax = {0.5 / T.W, 0.5 / T.H, (T.W - 0.5) / T.W,
                                                       (T.H - 0.5) / T.H};
  F2 HistoryBufferUV = {
      HistoryScreenPosition[0] * ScreenPosToHistoryBufferUV[0] + ScreenPosToHistoryBufferUV[2],
      HistoryScreenPosition[1] * ScreenPosToHistoryBufferUV[1] + ScreenPosToHistoryBufferUV[3]};
  HistoryBufferUV[0] =
      std::clamp(HistoryBufferUV[0], HistoryBufferUVMinMax[0], HistoryBufferUVMinMax[2]);
  HistoryBufferUV[1] =
      std::clamp(HistoryBufferUV[1], HistoryBufferUVMinMax[1], HistoryBufferUVMinMax[3]);
  const FCatmullRomSamples Samples = GetBicubic2DCatmullRomSamples(HistoryBufferUV, Size, InvSize);
  F3 RawHistory0{};
  for (size_t i = 0; i < 5; i++) {
    F2 SampleUV = Samples.UV[i];
    for (size_t a = 0; a < 2; ++a) {
      if (Samples.UVDir[i][a] < 0) SampleUV[a] = std::max(SampleUV[a], HistoryBufferUVMinMax[a]);
      if (Samples.UVDir[i][a] > 0)
        SampleUV[a] = std::min(SampleUV[a], HistoryBufferUVMinMax[a + 2]);
    }
    const F3 c = T.HistoryBuffer.linear(SampleUV[0], SampleUV[1]);
    for (size_t k = 0; k < 3; ++k) RawHistory0[k] += c[k] * Samples.Weight[i];
  }
  for (double& v : RawHistory0) v *= Samples.FinalMultiplier;
  return RGBToYCoCg(RawHistory0);  // TransformSceneColor; HistoryPreExposureCorrection 1
}

// TemporalAA.usf TemporalAASample for the main pass (AA_FILTERED, AA_SAMPLES 5,
// AA_TONE, AA_YCOCG, AA_BICUBIC, AA_CLIP 0, HISTORY_CLAMPING_BOX_MIN_MAX),
// exposure 1, no responsive pixel, no dynamic velocity.
F3 TemporalAASample(const Textures& T, int x, int y, F2 TemporalJitterPixels, bool bCameraCut) {
  const double CurrentFrameWeight = 0.04;  // r.TemporalAACurrentFrameWeight
  const SampleWeightParameters P = SetupSampleWeightParameters(TemporalJitterPixels);
  const F2 ViewportUV = {(x + 0.5) / T.W, (y + 0.5) / T.H};
  const F2 ScreenPos = {ViewportUV[0] * 2 - 1, 1 - ViewportUV[1] * 2};  // ViewportUVToScreenPos
  // PrecacheInputSceneColor: the 3x3 around the nearest input pixel, clamped.
  static const int kOffsets3x3[9][2] = {{-1, -1}, {0, -1}, {1, -1}, {-1, 0}, {0, 0},
                                        {1, 0},   {-1, 1}, {0, 1},  {1, 1}};
  std::array<F3, 9> Neighbors;
  for (size_t i = 0; i < 9; i++) {
    const int cx =
        std::clamp(static_cast<int>(ViewportUV[0] * T.W) + kOffsets3x3[i][0], 0, T.W - 1);
    const int cy =
        std::clamp(static_cast<int>(ViewportUV[1] * T.H) + kOffsets3x3[i][1], 0, T.H - 1);
    Neighbors[i] = RGBToYCoCg(T.InputSceneColor.load(cx, cy));
  }
  // Camera motion: ClipToPrevClip gives the previous screen position.
  const F2 q = T.Previous[static_cast<size_t>(y * T.W + x)];
  const F2 PrevScreen = {(q[0] + 0.5) / T.W * 2 - 1, 1 - (q[1] + 0.5) / T.H * 2};
  const F2 BackN = {ScreenPos[0] - PrevScreen[0], ScreenPos[1] - PrevScreen[1]};
  const F2 BackTemp = {BackN[0] * T.W, BackN[1] * T.H};  // OutputViewportSize.xy
  const double Velocity = std::sqrt(BackTemp[0] * BackTemp[0] + BackTemp[1] * BackTemp[1]);
  const F2 HistoryScreenPosition = {ScreenPos[0] - BackN[0], ScreenPos[1] - BackN[1]};
  const bool OffScreen =
      std::max(std::abs(HistoryScreenPosition[0]), std::abs(HistoryScreenPosition[1])) >= 1.0;
  // FilterCurrentFrameInputSamples
  static const size_t kPlusIndexes3x3[5] = {1, 3, 4, 5, 7};
  F3 NeighborsColor{};
  double NeighborsFinalWeight = 0;
  for (size_t i = 0; i < 5; i++) {
    const F3& Color = Neighbors[kPlusIndexes3x3[i]];
    const double SampleFinalWeight = P.PlusWeights[i] * HdrWeightY(Color[0], 1);
    for (size_t k = 0; k < 3; ++k) NeighborsColor[k] += SampleFinalWeight * Color[k];
    NeighborsFinalWeight += SampleFinalWeight;
  }
  F3 Filtered;
  for (size_t k = 0; k < 3; ++k) Filtered[k] = NeighborsColor[k] * (1 / NeighborsFinalWeight);
  // ComputeNeighborhoodBoundingbox, HISTORY_CLAMPING_BOX_MIN_MAX
  F3 NeighborMin, NeighborMax;
  for (size_t k = 0; k < 3; ++k) {
    NeighborMin[k] = std::min(
        {Neighbors[1][k], Neighbors[3][k], Neighbors[4][k], Neighbors[5][k], Neighbors[7][k]});
    NeighborMax[k] = std::max(
        {Neighbors[1][k], Neighbors[3][k], Neighbors[4][k], Neighbors[5][k], Neighbors[7][k]});
  }
  F3 History = SampleHistory(T, HistoryScreenPosition);
  const bool IgnoreHistory = OffScreen || bCameraCut;
  const double LumaHistory = History[0];  // before the clamp
  for (size_t k = 0; k < 3; ++k)
    History[k] = std::clamp(History[k], NeighborMin[k], NeighborMax[k]);  // ClampHistory
  // COMPUTE BLEND AMOUNT
  const double LumaFiltered = Filtered[0];
  double BlendFinal = 1 * CurrentFrameWeight;  // FilteredTemporalWeight 1
  BlendFinal = lerp(BlendFinal, 0.2, saturate(Velocity / 40));
  BlendFinal =
      std::max(BlendFinal, saturate(0.01 * LumaHistory / std::abs(LumaFiltered - LumaHistory)));
  if (bCameraCut) BlendFinal = 1.0;
  if (IgnoreHistory) History = Filtered;
  const double FilterWeight = HdrWeightY(Filtered[0], 1), HistoryWeight = HdrWeightY(History[0], 1);
  const F2 Weights = WeightedLerpFactors(HistoryWeight, FilterWeight, BlendFinal);
  F3 Out;
  for (size_t k = 0; k < 3; ++k) Out[k] = History[k] * Weights[0] + Filtered[k] * Weights[1];
  Out = YCoCgToRGB(Out);
  for (double& v : Out) v = -std::min(-v, 0.0);  // AA_NAN
  return Out;
}

Plane plane_of(const std::vector<F3>& t, int w, int h) {
  Plane p{w, h, 3, {}};
  for (const F3& c : t) p.values.insert(p.values.end(), c.begin(), c.end());
  return p;
}

// Every pixel of hand-made frames: random colours (some over 1, where the
// luma weights matter), pans that reach past the border (off-screen
// history), a still one (the history read at texel centres, and the
// low-contrast floor), a fast one (the velocity's lerp saturated), flat and
// black frames (|dY| = 0: the floor is +inf or NaN in the shader), jitters
// of every sign, and a cut.
TEST(Ue4MainPass, EveryPixelIsTheShadersArithmetic) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> colour(0, 1.4);
  struct Case {
    int w, h;
    F2 motion;    // the previous point minus the pixel
    F2 jitter;    // TemporalJitterPixels
    double flat;  // < 0: random colours; else every input and history pixel this grey
    bool cut;
  };
  const std::vector<Case> cases = {
      {7, 5, {0.37, -0.21}, {0.3, -0.17}, -1, false},
      {7, 5, {-1.6, 2.45}, {-0.45, 0.42}, -1, false},
      {6, 6, {0, 0}, {0, 0}, -1, false},
      {6, 4, {0.5, 0.5}, {0.12, 0.49}, -1, false},
      {40, 3, {-22.3, 0.1}, {-0.2, 0.05}, -1, false},
      {5, 5, {0.25, 0}, {0.1, 0.1}, 0.6, false},
      {5, 5, {0, 0}, {0.2, -0.3}, 0, false},
      {7, 5, {0.37, -0.21}, {0.3, -0.17}, -1, true},
  };
  for (size_t n = 0; n < cases.size(); ++n) {
    const Case& c = cases[n];
    Textures T;
    T.W = T.InputSceneColor.W = T.HistoryBuffer.W = c.w;
    T.H = T.InputSceneColor.H = T.HistoryBuffer.H = c.h;
    for (int i = 0; i < c.w * c.h; ++i) {
      const auto pick = [&] {
        return c.flat < 0 ? F3{colour(rng), colour(rng), colour(rng)} : F3{c.flat, c.flat, c.flat};
      };
      T.InputSceneColor.texels.push_back(pick());
      T.HistoryBuffer.texels.push_back(pick());
      T.Previous.push_back({i % c.w + c.motion[0], i / c.w + c.motion[1]});
    }
    const std::vector<double> input_values = plane_of(T.InputSceneColor.texels, c.w, c.h).values;
    const SampleFrame frame{c.w, c.h, 3, input_values.data()};
    const Plane history = plane_of(T.HistoryBuffer.texels, c.w, c.h);
    // The library places the sample at minus the API's jitter.
    const auto weights = ue4_plus_weights({-c.jitter[0], -c.jitter[1]});
    for (int y = 0; y < c.h; ++y)
      for (int x = 0; x < c.w; ++x) {
        const F3 want = TemporalAASample(T, x, y, c.jitter, c.cut);
        const Vec2 q{x + c.motion[0], y + c.motion[1]};
        Ue4Colour previous;
        const bool valid = !c.cut && ue4_history_sample(history, q, previous);
        const Ue4Colour got =
            ue4_main_pass(ue4_gather(frame, x, y), weights, valid ? &previous : nullptr,
                          std::hypot(q.x - x, q.y - y));
        for (size_t k = 0; k < 3; ++k)
          EXPECT_NEAR(got[k], want[k], 1e-12) << "case " << n << " pixel " << x << "," << y;
      }
  }
}

// Numbers the shader's formulas give by hand: a still, converged pixel
// whose history is within 1 % of its input takes the input outright (the
// floor saturates), a pixel moving 20 px a frame takes 0.2 of it before the
// luma weights, a centred jitter weighs the plus's arms exp(-2.29) of its centre.
TEST(Ue4MainPass, HandNumbers) {
  const auto w = ue4_plus_weights({0, 0});
  const double arm = std::exp(-2.29);
  EXPECT_NEAR(w[2], 1 / (1 + 4 * arm), 1e-15);
  EXPECT_NEAR(w[0], arm / (1 + 4 * arm), 1e-15);
  // A uniform grey g: Y = 4 g, every luma weight 1 / (4 g + 4).
  Ue4Neighbourhood flat;
  flat.fill(ue4_ycocg({0.5, 0.5, 0.5}));
  const Ue4Colour near{0.502, 0.502, 0.502};  // clamped to the box's 0.5 anyway
  EXPECT_NEAR(ue4_main_pass(flat, w, &near, 0)[0], 0.5, 1e-15);
  // An edge: the pixel's plus holds 0 and 1, the history sits at 0.25 inside the box.
  Ue4Neighbourhood edge;
  edge.fill(ue4_ycocg({0, 0, 0}));
  edge[5] = edge[7] = ue4_ycocg({1, 1, 1});
  const Ue4Colour hist{0.25, 0.25, 0.25};
  double filtered = 0, total = 0;
  for (size_t k = 0; k < 5; ++k) {
    const double v = k >= 3 ? 1.0 : 0.0, h = 1 / (4 * v + 4);
    filtered += w[k] * h * v;
    total += w[k] * h;
  }
  filtered /= total;
  const auto blended = [&](double alpha) {
    const double a = (1 - alpha) / (4 * 0.25 + 4), b = alpha / (4 * filtered + 4);
    return (a * 0.25 + b * filtered) / (a + b);
  };
  EXPECT_NEAR(ue4_main_pass(edge, w, &hist, 0)[1], blended(0.04), 1e-15);
  EXPECT_NEAR(ue4_main_pass(edge, w, &hist, 20)[1], blended(0.2), 1e-15);
  EXPECT_NEAR(ue4_main_pass(edge, w, &hist, 10)[1], blended(0.12), 1e-15);
  EXPECT_NEAR(ue4_main_pass(edge, w, nullptr, 3)[1], filtered, 1e-15);  // a cut
}

}  // namespace ue4_shader
}  // namespace aapat
