// What an engine pastes into code for a sequence.
//  - A jitter (one sample per frame): a constant array of the K offsets in
//    pixels from the pixel centre, for HLSL, GLSL or C++, with +x right and
//    +y up (aapat's convention) or +y down (screen rows, as Direct3D,
//    Vulkan and Metal count them); the header says which. An upscaler such
//    as FSR 2 takes these pixel offsets directly (ffxFsr2GetJitterOffset
//    returns the same units); the projection's translation is then
//    2 x / width and -2 y / height in clip space for +y down offsets.
//    Numbers are printed with 17 significant digits: exact as doubles.
//  - Several samples per frame (alternating MSAA): every frame snapped to
//    the 1/16 lattice and exported for an API profile as the pattern export
//    does (io/api_export.h), one block per frame.
#pragma once

#include <string>
#include <string_view>

#include "aapat/core/hardware_layout.h"
#include "aapat/temporal/sequence/sequence.h"

namespace aapat {

enum class ExportLanguage { hlsl, glsl, cpp };
ExportLanguage parse_export_language(std::string_view name);  // hlsl, glsl, c++ (cpp)

// Throws Error when the sequence is not a jitter (more than one sample in a
// frame, a tile).
std::string export_jitter(const Sequence& s, ExportLanguage language, bool y_down);

// One block per frame for the profile; throws Error naming the frame that
// does not fit (too many samples for the profile, a tile the grid cannot hold).
std::string export_msaa_sequence(const Sequence& s, const ApiProfile& profile);

}  // namespace aapat
