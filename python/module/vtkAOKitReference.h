#ifndef vtkAOKitReference_h
#define vtkAOKitReference_h
// vtkAOKitReference: the kit's Embree ground truth for what a renderer shows, and the bench's
// error metrics. Compute() casts one CPU primary ray through each pixel centre of the renderer's
// viewport (its active camera, perspective or parallel) into the meshes of its visible casting props (the
// meshes the families themselves collect: actors, composite and glyph mappers, assemblies), then
// `Samples` AO rays per hit over the hit facet's hemisphere, cosine weighted, within `Radius`,
// weighted by `Falloff`. Output: occlusion in [0, 1], -1 where the ray hits nothing, bottom row
// first. ProgressEvent carries the fraction done (a double) while it runs.
#include <string>

#include "aokitVTKModule.h"
#include <vtkObject.h>

class vtkFloatArray;
class vtkRenderer;

class AOKITVTK_EXPORT vtkAOKitReference : public vtkObject
{
public:
  static vtkAOKitReference* New();
  vtkTypeMacro(vtkAOKitReference, vtkObject);

  // AO rays per pixel, 1..65536 (default 256).
  vtkSetMacro(Samples, int);
  vtkGetMacro(Samples, int);
  // AO radius R in world units, > 0 (default 1).
  vtkSetMacro(Radius, double);
  vtkGetMacro(Radius, double);
  // binary (default), wendland, sqrt or exponential.
  vtkSetStdStringFromCharMacro(Falloff);
  vtkGetCharFromStdStringMacro(Falloff);
  // Same seed, same rays: bit-identical output (default 1).
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);

  // Fills `ao` (one component per pixel) and `size` (width, height). Returns false on bad
  // settings, a parallel projection, a renderer without size or casting geometry; GetLastError()
  // says why in one line.
  bool Compute(vtkRenderer* renderer, vtkFloatArray* ao, int size[2]);

  // The bench's metrics of `test` against `reference` (both width x height, -1 = no surface),
  // over the pixels both cover: out = RMSE, mean absolute error, 99th percentile of the
  // absolute error, SSIM of 1 - AO, pixels compared. Returns false on mismatched sizes or no
  // common pixel.
  bool Compare(vtkFloatArray* test, vtkFloatArray* reference, int width, int height, double out[5]);

  std::string GetLastError() { return LastError; }

protected:
  vtkAOKitReference() = default;
  ~vtkAOKitReference() override = default;

  int Samples = 256;
  double Radius = 1.0;
  std::string Falloff = "binary";
  int Seed = 1;
  std::string LastError;

private:
  vtkAOKitReference(const vtkAOKitReference&) = delete;
  void operator=(const vtkAOKitReference&) = delete;
};

#endif
