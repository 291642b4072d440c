// A capture's mean radiance (capture::frameRadiance): the linear frame's mean, non-finite pixels
// counted as black.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "capture/capture.hpp"

namespace onelight {
namespace {

TEST(CaptureRadiance, MeanOfTheLinearFrameWithNonFinitePixelsAsBlack) {
    render::CapturedFrame frame;
    frame.width = 2;
    frame.height = 1;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    frame.linearRgba = {1.0f, 2.0f, 3.0f, 1.0f, 3.0f, nan, 5.0f, 1.0f};
    const nlohmann::json r = capture::frameRadiance(frame);
    EXPECT_DOUBLE_EQ(r["mean_rgb"][0].get<double>(), 2.0);
    EXPECT_DOUBLE_EQ(r["mean_rgb"][1].get<double>(), 1.0);  // the NaN is black, not the mean's
    EXPECT_DOUBLE_EQ(r["mean_rgb"][2].get<double>(), 4.0);
    EXPECT_NEAR(r["mean_luminance"].get<double>(), 0.2126 * 2.0 + 0.7152 * 1.0 + 0.0722 * 4.0,
                1e-12);
}

TEST(CaptureRadiance, EmptyFrameIsBlack) {
    const nlohmann::json r = capture::frameRadiance(render::CapturedFrame{});
    EXPECT_EQ(r["mean_luminance"].get<double>(), 0.0);
}

}  // namespace
}  // namespace onelight
