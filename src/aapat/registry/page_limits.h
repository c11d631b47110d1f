// The explorer page's own limits (docs/explorer.md): what keeps a drag
// interactive on one thread in a browser, tighter than the command line's.
// Defined here, with every other limit, so that docs/limits.md lists them.
#pragma once

namespace aapat {

inline constexpr int kMaxPageViewSize = 256;           // the rendered view's side, pixels
inline constexpr int kMaxPagePoints = 16384;           // a point set's points
inline constexpr int kMaxPageSpectrumSize = 256;       // a spectrum's side, frequencies
inline constexpr int kMaxPageStarts = 1024;            // an optimization's starts
inline constexpr int kMaxPageIterations = 1000000;     // iterations per start
inline constexpr int kMaxPageReferenceSamples = 4096;  // reference samples per pixel
inline constexpr int kMaxPageSeed = 2147483647;        // seeds a JavaScript number holds exactly
// A link's characters after '#': below Chromium's 2 MB address limit, so that
// a link the page writes is one a browser opens. A design past it is saved
// as a file instead, and a longer link is refused with a message.
inline constexpr int kMaxPageLinkBytes = 1 << 20;

}  // namespace aapat
