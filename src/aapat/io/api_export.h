// What a programmer pastes into code: a hardware layout as the API's sample
// position array (its units, its order, its pixel grid) and a resolve
// function (HLSL, GLSL or the Metal shading language) that reads the samples
// each output pixel's kernel needs, its neighbours' shared samples included,
// and applies the weights. The first line is machine-readable, and the
// arrays are printed exactly, so `aapat import` reads the text back.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/hardware_layout.h"
#include "aapat/core/objective.h"

namespace aapat {

enum class ShaderLanguage { kHlsl, kGlsl, kMsl };

ShaderLanguage default_shader(const ApiProfile& profile);  // HLSL, GLSL (Vulkan, GL), MSL
ShaderLanguage parse_shader_language(std::string_view name);

// `notes`: comment lines placed under the header (E2, cost, provenance).
std::string export_layout(const HardwareLayout& layout, ShaderLanguage shader,
                          const std::vector<std::string>& notes = {});

// What `aapat export` writes (and the explorer page's export): `pattern`
// (snapped to the 1/16 lattice first when `snap`) as `profile`'s arrays and
// resolve shader on a grid_w x grid_h pixel grid (0: the pattern's tile),
// with notes giving its E2 under `objective`, what it was designed for, and
// its cost.
std::string export_pattern(const Pattern& pattern, const ApiProfile& profile,
                           const Objective& objective, ShaderLanguage shader, bool snap = false,
                           int grid_w = 0, int grid_h = 0);

// Throws Error, naming `what` (the flag or argument), unless a grid_w x
// grid_h pixel grid is one `profile` takes: a choice of grid (not a fixed
// one) and 1 to max_grid pixels a side. The one check of the CLI's --grid
// and Python's grid=.
void check_export_grid(const ApiProfile& profile, int grid_w, int grid_h, std::string_view what);

// The numbers of a C-like initializer: comments, identifiers (int3, the f of
// 0.5f) and punctuation skipped.
std::vector<double> numbers_in(std::string_view code);

// Reads an exported text back; `source` names it in error messages.
HardwareLayout parse_export(std::string_view text, std::string_view source);

}  // namespace aapat
