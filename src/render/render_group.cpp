#include "render/render_group.h"

#include "render/film.h"
#include "render/image_io.h"
#include "render/tile_progress.h"

namespace eyetrace {

bool RenderGroup::complete(const TileProgress& tp, int spp) {
  // An adaptive render shares every pass (every rank's progress is whole); a uniform one knows
  // its own tiles: the job is complete when every rank's are.
  if (tp.adaptive()) return tp.complete(spp);
  bool own = true;
  for (size_t t = 0; t < tp.done.size(); ++t)
    if (owns_tile(t, tp.done.size()) && tp.done[t] < spp) own = false;
  return !any(!own);
}

Image RenderGroup::collect_image(const Film& film, TileProgress&) { return film.image(); }

}  // namespace eyetrace
