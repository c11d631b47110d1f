#include "aapat/render/reference.h"

#include "aapat/core/filter_catalog.h"

namespace aapat {

Image render_reference(const Scene& scene, int width, int height, const ReferenceSettings& r,
                       double offset) {
  Sampling s;
  s.generator = "jittered";
  s.samples = r.samples;
  s.seed = r.seed;
  return render(scene, width, height, s, make_filter(r.filter), nullptr, offset);
}

}  // namespace aapat
