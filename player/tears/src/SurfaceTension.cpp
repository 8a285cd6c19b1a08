#include "SurfaceTension.h"
#include "SurfaceTension_Akinci2013.h"
#include "SurfaceTension_Mueller2003.h"

namespace lacrima::tears {

std::unique_ptr<SurfaceTension> SurfaceTension::create(SurfaceTensionModel model,
                                                       const ScaledParameters& p) {
  if (model == SurfaceTensionModel::Akinci)
    return std::make_unique<SurfaceTension_Akinci2013>(p.h, p.tensionGamma, p.restDensity);
  return std::make_unique<SurfaceTension_Mueller2003>(p.h, p.tensionSigma);
}

}  // namespace lacrima::tears
