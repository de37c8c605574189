#pragma once
// What vtkAOKitPass needs of one family: its pass as a DeferredAOPass and its settings as text
// through the family's schema (settings/Schema.h), the one table C++, the CLI, scene files and
// Python share.
#include <memory>
#include <string>
#include <vector>

#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

#include "render/DeferredAOPass.h"
#include "settings/SettingInfo.h"

namespace aokit::python {

class PassFamily {
 public:
  virtual ~PassFamily() = default;
  virtual DeferredAOPass* pass() const = 0;
  virtual const std::string& name() const = 0;
  // Throws std::invalid_argument (one line) on an unknown key or a bad value; keeps the old value.
  virtual void set(const std::string& key, const std::string& value) = 0;
  virtual std::string get(const std::string& key) const = 0;
  virtual std::vector<SettingInfo> infos() const = 0;
};

// Pass: ObscurancePass, HybridPass or FieldPass; schema: that family's table.
template <class Pass, class Settings, class SchemaT>
class FamilyOf : public PassFamily {
 public:
  explicit FamilyOf(const SchemaT& schema) : schema_(schema), pass_(vtkSmartPointer<Pass>::New()) {}
  DeferredAOPass* pass() const override { return pass_; }
  Pass* typed() const { return pass_; }
  const std::string& name() const override { return schema_.family(); }
  void set(const std::string& key, const std::string& value) override {
    Settings s = pass_->GetSettings();
    schema_.set(s, key, value);
    pass_->SetSettings(s);  // validates every range and rule; throws and keeps the old settings
  }
  std::string get(const std::string& key) const override { return schema_.get(pass_->GetSettings(), key); }
  std::vector<SettingInfo> infos() const override { return schema_.infos(); }

 private:
  const SchemaT& schema_;
  vtkSmartPointer<Pass> pass_;
};

}  // namespace aokit::python

#include "vtkAOKitPass.h"

struct vtkAOKitPass::Internals {
  std::unique_ptr<aokit::python::PassFamily> family;
  std::string error;
  vtkWeakPointer<vtkRenderer> last;  // the renderer drawn last
};
