#include "level_knobs.hpp"

#include <cstdio>
#include <utility>

namespace onelight::lab {

namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// The knob's values: all of them, or only the first when quick.
std::vector<std::string> pick(std::vector<std::string> values, bool quick) {
    if (quick) values.resize(1);
    return values;
}

KnobSetting setting(std::string knob, std::string value, std::vector<std::string> bakeArgs,
                    std::vector<std::string> frameArgs) {
    KnobSetting s;
    s.knob = std::move(knob);
    s.value = std::move(value);
    s.bakeArgs = std::move(bakeArgs);
    s.frameArgs = std::move(frameArgs);
    return s;
}

}  // namespace

std::vector<std::string> baselineBakeArgs() {
    return {"--quality", "draft"};
}

std::vector<KnobSetting> levelKnobs(double levelTexelsPerMetre, const std::string& levelGlossMips,
                                    bool patchable, bool quick) {
    std::vector<KnobSetting> out;
    out.push_back(setting("baseline", "draft bake; runtime defaults", {}, {}));
    // The runtime's knobs: the baseline's package, one onelight option changed.
    for (const std::string& v : pick({"1", "4"}, quick))
        out.push_back(setting("MSAA", v + "x", {}, {"--msaa", v}));
    // Post-process anti-aliasing against MSAA (docs/frame-rate.md, "Anti-aliasing").
    for (const std::string& v : pick({"1", "4"}, quick))
        out.push_back(setting("MSAA + FXAA", v + "x + FXAA", {}, {"--msaa", v, "--fxaa"}));
    for (const std::string& v : pick({"16", "4"}, quick))
        out.push_back(setting("anisotropy", v, {}, {"--anisotropy", v}));
    out.push_back(setting("probes", "off", {}, {"--no-probes"}));
    for (const std::string& v : pick({"256", "512", "2048"}, quick))
        out.push_back(setting("shadow-map size", v, {}, {"--shadow-map-size", v}));
    for (const std::string& v : pick({"10", "20", "80"}, quick))
        out.push_back(setting("shadow distance m", v, {}, {"--shadow-distance", v}));
    // The baker's knobs: a bake each.
    for (const std::string& v : pick({"default", "high"}, quick))
        out.push_back(setting("bake quality", v, {"--quality", v}, {}));
    for (double f : quick ? std::vector<double>{0.5} : std::vector<double>{0.25, 0.5, 2.0}) {
        const std::string v = number(levelTexelsPerMetre * f);
        out.push_back(setting("texels per metre", v, {"--texels-per-metre", v}, {}));
    }
    for (const std::string& v : pick({"2", "0.5", "4"}, quick))
        out.push_back(setting("grid cell m", v, {"--grid-cell", v}, {}));
    for (const std::string& v : pick({"4", "2", "16"}, quick))
        out.push_back(setting("probe spacing m", v, {"--probe-spacing", v}, {}));
    for (const std::string& v : pick({"16", "64"}, quick))
        out.push_back(setting("probe face size", v, {"--probe-face-size", v}, {}));
    // The error budget's choices (bake/budget/), each with the error it predicts: the report
    // sets the prediction against the measured error.
    for (const std::string& v : pick({"5%", "2%", "10%"}, quick))
        out.push_back(setting("error budget", v, {"--error-budget", v}, {}));
    // The material pipeline's per-level choice: a patched copy of the glTF, a bake each.
    if (patchable) {
        std::vector<std::string> others;
        for (const char* v : {"blit", "wwii", "black_ops", "clean"})
            if (v != levelGlossMips) others.push_back(v);
        for (const std::string& v : pick(others, quick)) {
            KnobSetting s = setting("gloss mips", v, {}, {});
            s.levelKey = "gloss_mips";
            s.levelValue = v;
            out.push_back(s);
        }
    }
    return out;
}

std::vector<MissingKnob> missingKnobs() {
    return {
        {"specular model",
         "not a runtime choice yet: the shaders compile GGX-Smith only (the "
         "lab's brdf-report measures the candidates on their own)"},
        {"environment BRDF (fit or table)",
         "not a runtime choice yet: one is compiled in (brdf-report measures both)"},
        {"diffuse model (extras.onelight.diffuse)",
         "a change of the BRDF itself, not an approximation of one: the reference follows it, "
         "so there is no fixed truth to measure against"},
    };
}

}  // namespace onelight::lab
