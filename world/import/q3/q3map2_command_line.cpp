#include "world/import/q3/q3map2_command_line.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace onelight::world::q3 {
namespace {

std::vector<std::string> tokens(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string t; in >> t;) out.push_back(t);
    return out;
}

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

// The number a whole token spells, or kNone.
double numberOf(const std::string& token) {
    if (token.empty()) return kNone;
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    return (end && *end == '\0' && errno == 0 && std::isfinite(v)) ? v : kNone;
}

std::string trimmed(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return {};
    return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

std::string number(float v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

}  // namespace

Q3map2LightOptions readQ3map2LightOptions(const std::vector<MapEntity>& entities,
                                          const std::string& where) {
    Q3map2LightOptions o;
    if (entities.empty()) return o;
    const std::string line = entities[0].get("_q3map2_cmdline");
    std::string stage, scaleStage;
    for (size_t at = 0; at <= line.size();) {
        const size_t end = std::min(line.find(';', at), line.size());
        const std::string part = line.substr(at, end - at);
        const std::vector<std::string> t = tokens(part);
        for (const std::string& word : t)
            if (word == "-light") stage = part, scaleStage.clear();
        if (!stage.empty() && !t.empty() && t[0] == "-scale") scaleStage = part;
        at = end + 1;
    }
    if (stage.empty()) return o;
    if (!scaleStage.empty()) {
        // ScaleBSP's arguments: [-tex] [-spawn_ref V] then one scale, or X Y Z: the trailing
        // numbers.
        std::vector<double> numbers;
        const std::vector<std::string> t = tokens(scaleStage);
        for (size_t i = t.size(); i-- > 1 && std::isfinite(numberOf(t[i]));)
            numbers.insert(numbers.begin(), numberOf(t[i]));
        if (t.size() >= 3 && t[t.size() - 3] == "-spawn_ref" && !numbers.empty())
            numbers.erase(numbers.begin());  // -spawn_ref's value, not a scale
        const bool uniform =
            numbers.size() == 1 ||
            (numbers.size() == 3 && numbers[0] == numbers[1] && numbers[1] == numbers[2]);
        if (uniform && numbers[0] > 0.0 && numbers[0] < 1e6)
            o.scaledAfterLight = float(numbers[0]);
        else
            o.notes.push_back(where + ": worldspawn _q3map2_cmdline: the stage '" +
                              trimmed(scaleStage).substr(0, 48) +
                              "' after -light ignored: expected one positive scale (the map was "
                              "lit before it was scaled)");
    }
    o.recorded = true;
    o.lightStage = trimmed(stage);
    const std::vector<std::string> t = tokens(stage);
    for (size_t i = 0; i < t.size(); ++i) {
        const std::string& name = t[i];
        // The option's value, when it takes one and it is a number in range; else a note.
        const auto value = [&](double lowest, bool whole) -> double {
            const double v = i + 1 < t.size() ? numberOf(t[i + 1]) : kNone;
            const bool ok = std::isfinite(v) && v >= lowest && (!whole || v == std::floor(v));
            if (!ok) {
                std::string note = where;
                note.append(": worldspawn _q3map2_cmdline: ").append(name).append(" ");
                if (i + 1 < t.size())
                    note.append("'").append(t[i + 1], 0, 32).append("'");
                else
                    note.append("(nothing)");
                note.append(" ignored: expected ")
                    .append(whole ? "a whole number >= " : "a number >= ")
                    .append(number(float(lowest)));
                o.notes.push_back(std::move(note));
            }
            ++i;
            return ok ? v : kNone;
        };
        const auto scale = [&](std::initializer_list<float*> targets) {
            const double v = value(0.0, false);
            if (std::isfinite(v))
                for (float* f : targets) *f *= float(v);
        };
        if (name == "-scale") {
            const double v = value(0.0, false);
            if (std::isfinite(v)) {
                for (float* f :
                     {&o.pointScale, &o.spotScale, &o.areaScale, &o.skyScale, &o.bounceScale})
                    *f *= float(v);
            }
        } else if (name == "-point" || name == "-pointscale") {
            scale({&o.pointScale, &o.spotScale});
        } else if (name == "-spherical" || name == "-sphericalscale") {
            scale({&o.pointScale});
        } else if (name == "-spot" || name == "-spotscale") {
            scale({&o.spotScale});
        } else if (name == "-area" || name == "-areascale") {
            scale({&o.areaScale});
        } else if (name == "-sky" || name == "-skyscale") {
            scale({&o.skyScale});
        } else if (name == "-bouncescale") {
            scale({&o.bounceScale});
        } else if (name == "-bounce") {
            const double v = value(0.0, true);
            if (std::isfinite(v)) o.bounces = uint32_t(std::min(v, 1e6));
        } else if (name == "-gamma") {
            const double v = value(1e-3, false);
            if (std::isfinite(v)) o.encoding.gamma = float(v);
        } else if (name == "-exposure") {
            const double v = value(0.0, false);
            if (std::isfinite(v)) o.encoding.exposure = float(v);
        } else if (name == "-compensate") {
            const double v = value(0.0, false);
            if (std::isfinite(v) && v > 0.0) o.encoding.compensate = float(v);  // q3map2: <= 0 is 1
        } else if (name == "-brightness") {
            const double v = value(1e-6, false);
            if (std::isfinite(v)) o.encoding.brightness = float(v);
        } else if (name == "-contrast") {
            const double v = value(-255.0, false);
            if (std::isfinite(v)) {
                // q3map2: clamped to 255, then a factor (259 (c + 255)) / (255 (259 - c)).
                const double c = std::min(v, 255.0);
                o.encoding.contrast = float(259.0 * (c + 255.0) / (255.0 * (259.0 - c)));
            }
        } else if (name == "-sRGBlight" || name == "-sRGB") {
            o.encoding.srgb = true;
        } else if (name == "-nosRGBlight" || name == "-nosRGB") {
            o.encoding.srgb = false;
        } else if (name == "-dirty") {
            o.dirt = true;
        }
    }
    return o;
}

float compensateShownByPages(const std::vector<uint8_t>& rgbPages) {
    std::vector<uint64_t> count(256, 0);
    for (size_t i = 0; i + 2 < rgbPages.size(); i += 3)
        ++count[std::max({rgbPages[i], rgbPages[i + 1], rgbPages[i + 2]})];
    uint32_t top = 255;
    while (top > 0 && count[top] == 0) --top;
    if (top == 255 || top < 2 || count[top] < 16 || count[top] < 8 * count[top - 1]) return 1.0f;
    const double c = 255.0 / (double(top) + 0.5);
    const double quarter = std::round(4.0 * c) / 4.0;
    return float(std::abs(quarter - c) <= 0.01 * c ? quarter : c);
}

std::string Q3map2LightOptions::summary() const {
    if (!recorded)
        return std::string(
                   "q3map2 options: not recorded (no _q3map2_cmdline -light stage); its "
                   "defaults assumed: no bounces, no dirt, lightmap bytes linear") +
               (compensateInferred
                    ? ", but its lightmaps clamp at " +
                          std::to_string(int(255.0f / encoding.compensate)) + ", as -compensate " +
                          number(encoding.compensate) + " makes them: decoded with it"
                    : std::string());
    std::string s = "q3map2 options: '" + lightStage.substr(0, 120) +
                    (lightStage.size() > 120 ? "..." : "") + "': ";
    s += bounces ? std::to_string(bounces) + " bounces" : std::string("no bounces");
    if (bounceScale != 1.0f) s += " at " + number(bounceScale) + "x q3map2's bounce scale";
    if (dirt) s += ", dirt (its ambient occlusion darkens corners; the engine's bake has none)";
    const auto scaleNote = [&](const char* what, float v) {
        if (v != 1.0f) s += std::string(", ") + what + " x" + number(v);
    };
    scaleNote("point lights", pointScale);
    scaleNote("spot lights", spotScale);
    scaleNote("surface lights", areaScale);
    scaleNote("sun and sky", skyScale);
    const ImportedLightEncoding& e = encoding;
    if (e.gamma != 1.0f || e.exposure > 0.0f || e.compensate != 1.0f || e.brightness != 1.0f ||
        e.contrast != 1.0f || e.srgb) {
        s += "; its lightmaps decoded from";
        if (e.brightness != 1.0f) s += " brightness " + number(e.brightness);
        if (e.gamma != 1.0f) s += " gamma " + number(e.gamma);
        if (e.exposure > 0.0f) s += " exposure " + number(e.exposure);
        if (e.compensate != 1.0f) s += " compensate " + number(e.compensate);
        if (e.contrast != 1.0f) s += " contrast x" + number(e.contrast);
        if (e.srgb) s += " sRGB";
    }
    if (scaledAfterLight != 1.0f)
        s += "; the map scaled " + number(scaledAfterLight) +
             "x after it was lit (its point and spot lights brightened to light it as then)";
    return s;
}

}  // namespace onelight::world::q3
