// The top of the particles' colour scale as the viewport draws it. Fixed: the model's own top (for the gas
// the write-up's 2.8 × the initial rms speed). Automatic, for a scene that says which rms its top was
// chosen for (SceneView::colourRms, the gas): the top rises with the rms of the colour values past that,
// so a heated gas keeps its gradient instead of turning all red; never below the model's top, so a cooled
// gas darkens as it should. Scenes with a designed fixed scale (the fluid, the tunnel) keep it.
#pragma once

#include "common/SceneView.h"

namespace pl::ui {

class ColourScale {
public:
    void setAutomatic(bool automatic) { automatic_ = automatic; }
    bool automatic() const { return automatic_; }
    // A new scene: the scale starts at the model's top.
    void restart() { factor_ = 1.0; }
    // Rescales the values and colourMax of `scene` in place (a no-op when fixed, for a scene without
    // colourRms, and for particles drawn from GPU buffers, whose values the CPU does not see).
    void apply(SceneView& scene);
    // How far the drawn top is above the model's (1 when fixed or not grown).
    double factor() const { return automatic_ ? factor_ : 1.0; }

private:
    bool automatic_ = true;
    double factor_ = 1.0; // smoothed over frames
};

} // namespace pl::ui
