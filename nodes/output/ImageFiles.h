#pragma once
// PNG output (through vtkPNGWriter) and raw float images, all written atomically.
#include <cstdint>
#include <string>
#include <vector>

namespace aokit {

// RGBA8 pixels, bottom row first (OpenGL order), as read back from a frame.
void writePNG(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba);
// Grey PNG of a [0,1] image (AO as occlusion shows dark where occluded: value = 1 - ao);
// pixels not covered are drawn in a flat blue so they are not mistaken for data.
void writeAOPNG(const std::string& path, int width, int height, const std::vector<float>& ao,
                const std::vector<std::uint8_t>& covered);
// Raw little-endian float32 image with a one-line text header: "AOKITF32 <width> <height>\n".
void writeFloatImage(const std::string& path, int width, int height, const std::vector<float>& values);
std::vector<float> readFloatImage(const std::string& path, int& width, int& height);

}  // namespace aokit
