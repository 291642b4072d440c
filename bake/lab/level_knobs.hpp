// The approximation knobs that level-report measures: one baseline configuration, then one knob
// changed at a time. A knob is either the baker's (a new bake) or the runtime's (the baseline's
// package drawn with another option).
#pragma once

#include <string>
#include <vector>

namespace onelight::lab {

struct KnobSetting {
    std::string knob;                    // e.g. "texels per metre"; "baseline" for the baseline
    std::string value;                   // as the table shows it, e.g. "8"
    std::vector<std::string> bakeArgs;   // added to the baseline's onelight-bake arguments
    std::vector<std::string> frameArgs;  // added to the baseline's onelight arguments
    // A level-wide extras.onelight key and value that a patched copy of the glTF bakes with
    // (gltf_patch.hpp); empty: the level as it is.
    std::string levelKey, levelValue;
};

// The baseline's arguments: the baker at draft quality and the level's own density, the
// runtime's defaults. Every setting's arguments come after these and override them.
[[nodiscard]] std::vector<std::string> baselineBakeArgs();

// The baseline, then the runtime's knobs (no new bake), then the baker's. `levelTexelsPerMetre`
// is the level's own density (its extras, else the baker's default); `levelGlossMips` its
// extras.onelight.gloss_mips; `patchable` whether a patched copy can be made (a .gltf), else the
// per-level knobs are left out; `quick` keeps one value per knob (tests).
[[nodiscard]] std::vector<KnobSetting> levelKnobs(double levelTexelsPerMetre,
                                                  const std::string& levelGlossMips, bool patchable,
                                                  bool quick);

// Knobs the issue names that are not a choice the engine offers yet, each with why: the report
// lists them instead of measuring them.
struct MissingKnob {
    std::string knob, why;
};
[[nodiscard]] std::vector<MissingKnob> missingKnobs();

}  // namespace onelight::lab
