#include "output/ImageFiles.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkUnsignedCharArray.h>

#include "output/AtomicFile.h"
#include "output/VtkErrorWindow.h"

namespace aokit {

void writePNG(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba) {
  if (rgba.size() != static_cast<std::size_t>(width) * height * 4)
    throw std::invalid_argument(path + ": pixel count does not match " + std::to_string(width) + "x" + std::to_string(height));
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  auto* dst = static_cast<std::uint8_t*>(image->GetScalarPointer());  // VTK images are bottom-up too
  std::memcpy(dst, rgba.data(), rgba.size());
  for (std::size_t i = 3; i < rgba.size(); i += 4) dst[i] = 255;  // frames leave alpha 0 on the background
  writeAtomically(path, [&](const std::string& tmp) {
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(tmp.c_str());
    writer->SetInputData(image);
    writer->Write();
    if (writer->GetErrorCode() != 0) {
      const std::string why = takeVtkError();
      throw std::runtime_error(path + ": cannot write PNG" + (why.empty() ? "" : " (" + why + ")"));
    }
  });
}

void writeAOPNG(const std::string& path, int width, int height, const std::vector<float>& ao,
                const std::vector<std::uint8_t>& covered) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  for (std::size_t i = 0; i < ao.size() && i * 4 < rgba.size(); ++i) {
    std::uint8_t* p = &rgba[i * 4];
    if (!covered.empty() && !covered[i]) {
      p[0] = 40, p[1] = 60, p[2] = 110, p[3] = 255;
      continue;
    }
    const float v = std::isfinite(ao[i]) ? std::clamp(1.0f - ao[i], 0.0f, 1.0f) : 0.0f;
    p[0] = p[1] = p[2] = static_cast<std::uint8_t>(std::lround(v * 255.0f));
    p[3] = 255;
  }
  writePNG(path, width, height, rgba);
}

void writeFloatImage(const std::string& path, int width, int height, const std::vector<float>& values) {
  writeStreamAtomically(path, [&](std::ostream& out) {
    out << "AOKITF32 " << width << " " << height << "\n";
    out.write(reinterpret_cast<const char*>(values.data()), static_cast<std::streamsize>(values.size() * sizeof(float)));
  });
}

std::vector<float> readFloatImage(const std::string& path, int& width, int& height) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::string magic;
  in >> magic >> width >> height;
  in.get();
  if (!in || magic != "AOKITF32" || width < 1 || height < 1 || width > 65536 || height > 65536)
    throw std::runtime_error(path + ": not an AOKITF32 float image");
  std::vector<float> values(static_cast<std::size_t>(width) * height);
  in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(values.size() * sizeof(float)));
  if (!in) throw std::runtime_error(path + ": truncated float image");
  return values;
}

}  // namespace aokit
