#include "albedo.hpp"

#include <optional>

#include "reflection_dots.hpp"
#include "shading.hpp"

namespace onelight::lab {

namespace {

using namespace onelight::glsl;

// f NoL (F = 1) of the shared float BRDF for one reflection.
double sharedLobe(const SpecularModel& model, float gloss, const Reflection& r) {
    const BrdfDots d = dotsOf(r);
    double D = specularD(model.ndf, d.NxH2, gloss);
    double V = specularV(model.ndf, model.vis, d.NoV, d.NoL, d.LoH, gloss);
    return 0.25 * D * V * r.NoL;
}

// The Blinn-Phong Lambda table the reference needs for this model and gloss (none otherwise).
std::optional<reference::BlinnPhongLambda> lambdaTableFor(const SpecularModel& model,
                                                          double gloss) {
    if (model.referenceNdf != reference::Ndf::kBlinnPhong) return std::nullopt;
    return reference::BlinnPhongLambda(reference::specPower(gloss));
}

double referenceLobe(const SpecularModel& model, double gloss, const Reflection& r,
                     const std::optional<reference::BlinnPhongLambda>& table) {
    return reference::smithLobe(model.referenceNdf, gloss, r.NoV, r.NoL, r.sin2H, r.cosH,
                                table ? &*table : nullptr);
}

double schlickWeight(double VoH) {
    return std::pow(1.0 - VoH, 5.0);
}

template <class Lobe>
ScaleBias albedoOf(const Lobe& lobe, double mu, double width) {
    Vec<2> sb = integrateHalfVectors<2>(mu, width, [&](const Reflection& r) {
        double w = lobe(r) * 4.0 * r.VoH;
        double f = schlickWeight(r.VoH);
        return Vec<2>{w * (1.0 - f), w * f};
    });
    return {sb[0], sb[1]};
}

}  // namespace

ScaleBias specularAlbedo(const SpecularModel& model, double mu, double gloss) {
    float g = float(gloss);
    return albedoOf([&](const Reflection& r) { return sharedLobe(model, g, r); }, mu,
                    lobeWidth(model, gloss));
}

ScaleBias referenceAlbedo(const SpecularModel& model, double mu, double gloss) {
    const auto table = lambdaTableFor(model, gloss);
    return albedoOf([&](const Reflection& r) { return referenceLobe(model, gloss, r, table); }, mu,
                    lobeWidth(model, gloss));
}

double lobeError(const SpecularModel& model, double mu, double gloss) {
    float g = float(gloss);
    const auto table = lambdaTableFor(model, gloss);
    Vec<2> e = integrateHalfVectors<2>(mu, lobeWidth(model, gloss), [&](const Reflection& r) {
        double ref = referenceLobe(model, gloss, r, table);
        return Vec<2>{std::abs(sharedLobe(model, g, r) - ref) * 4.0 * r.VoH, ref * 4.0 * r.VoH};
    });
    return e[0] / e[1];
}

}  // namespace onelight::lab
