#pragma once
#include <memory>

#include "core/AOTechnique.h"
#include "core/Group.h"

namespace aokit {

// Falloff of occlusion with the distance d to the occluder, over the AO radius R.
enum class Falloff : int { Binary, Wendland, Sqrt, Exponential };

// Root group of an AO-shaded scene: holds the AO radius and one swappable technique.
class AOScene : public Group {
 public:
  void accept(NodeVisitor& visitor) override;

  const std::shared_ptr<AOTechnique>& technique() const { return technique_; }
  void setTechnique(std::shared_ptr<AOTechnique> t) { technique_ = std::move(t); touch(); }

  double aoRadius() const { return aoRadius_; }
  void setAORadius(double r);  // throws on r <= 0 or non-finite
  Falloff falloff() const { return falloff_; }
  void setFalloff(Falloff f) { falloff_ = f; touch(); }

 private:
  std::shared_ptr<AOTechnique> technique_;
  double aoRadius_ = 1.0;
  Falloff falloff_ = Falloff::Binary;
};

using AOScenePtr = std::shared_ptr<AOScene>;

}  // namespace aokit
