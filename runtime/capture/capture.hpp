// Frame capture files: a tonemapped PNG, a linear HDR EXR (float, cd/m^2 before exposure) and a
// JSON sidecar. Each file is written to a temporary name and renamed when complete.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace onelight::capture {

/// 8-bit RGBA, top row first. False with `error` set on failure.
bool writePng(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<uint8_t>& rgba8, std::string& error);

/// 32-bit float RGBA, top row first, ZIP-compressed.
bool writeExr(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<float>& rgba, std::string& error);

/// Reads an EXR back as float RGBA (tests).
bool readExr(const std::string& path, uint32_t& width, uint32_t& height, std::vector<float>& rgba,
             std::string& error);

/// Reads a PNG as 8-bit RGBA (tests).
bool readPng(const std::string& path, uint32_t& width, uint32_t& height,
             std::vector<uint8_t>& rgba8, std::string& error);

/// Pretty-printed JSON.
bool writeJson(const std::string& path, const nlohmann::json& value, std::string& error);

}  // namespace onelight::capture
