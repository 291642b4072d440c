// The specular models the lab compares: a Black Ops "lego" combination of NDF and visibility,
// always with Schlick Fresnel on h.l.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "reference_brdf.hpp"

namespace onelight::lab {

struct SpecularModel {
    std::string_view name;        // as on the command line, e.g. "ggx_smith"
    int ndf;                      // NDF_* of shaders/brdf.glsl
    int vis;                      // VIS_*
    reference::Ndf referenceNdf;  // the NDF of its exact-Smith reference
};

// bp_none, bp_kelemen, bp_schlick, beck_smith, ggx_smith, in that order.
[[nodiscard]] const std::vector<SpecularModel>& specularModels();

// The model called `name`; throws std::invalid_argument naming the known ones.
[[nodiscard]] const SpecularModel& findModel(std::string_view name);

// Angular width of the model's NDF lobe at `gloss` (GGX alpha or Beckmann m), for quadrature.
[[nodiscard]] double lobeWidth(const SpecularModel& model, double gloss);

}  // namespace onelight::lab
