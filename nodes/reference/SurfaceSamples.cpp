#include "reference/SurfaceSamples.h"

#include <stdexcept>
#include <string>

namespace aokit {

namespace {

void checkSize(const char* what, std::size_t got, std::size_t want) {
  if (got != want)
    throw std::invalid_argument(std::string(what) + " holds " + std::to_string(got) + " values for " +
                                std::to_string(want) + " pixels");
}

void checkDims(int w, int h) {
  if (w < 0 || h < 0)
    throw std::invalid_argument("negative buffer size " + std::to_string(w) + "x" + std::to_string(h));
}

}  // namespace

void SurfaceSamples::resize(int w, int h) {
  checkDims(w, h);
  width = w;
  height = h;
  position.assign(pixelCount(), glm::vec3(0.0f));
  normal.assign(pixelCount(), glm::vec3(0.0f, 0.0f, 1.0f));
  covered.assign(pixelCount(), 0);
  receives.assign(pixelCount(), 1);
}

void SurfaceSamples::validate() const {
  checkDims(width, height);
  checkSize("SurfaceSamples::position", position.size(), pixelCount());
  checkSize("SurfaceSamples::normal", normal.size(), pixelCount());
  checkSize("SurfaceSamples::covered", covered.size(), pixelCount());
  checkSize("SurfaceSamples::receives", receives.size(), pixelCount());
}

void AOBuffer::resize(int w, int h, bool withError) {
  checkDims(w, h);
  width = w;
  height = h;
  ao.assign(pixelCount(), 0.0f);
  covered.assign(pixelCount(), 0);
  standardError.assign(withError ? pixelCount() : 0, 0.0f);
}

void AOBuffer::validate() const {
  checkDims(width, height);
  checkSize("AOBuffer::ao", ao.size(), pixelCount());
  checkSize("AOBuffer::covered", covered.size(), pixelCount());
  if (!standardError.empty()) checkSize("AOBuffer::standardError", standardError.size(), pixelCount());
}

}  // namespace aokit
