// The top of the particles' colour scale as the viewport draws it. Fixed: the model's own top (for the gas
// the write-up's 2.8 × the initial rms speed). Automatic: the model's top times how much the particles'
// rms colour value has grown since the scene started, so a heated gas keeps its gradient instead of
// turning all red; never below the model's top, so a cooled gas darkens as it should.
#pragma once

#include "common/SceneView.h"

namespace pl::ui {

class ColourScale {
public:
    void setAutomatic(bool automatic) { automatic_ = automatic; }
    bool automatic() const { return automatic_; }
    // A new scene: its next frame is the reference the growth is measured from.
    void restart();
    // Rescales the values and colourMax of `scene` in place (a no-op when fixed, for categories, and for
    // particles drawn from GPU buffers, whose values the CPU does not see).
    void apply(SceneView& scene);
    // How far the drawn top is above the model's (1 when fixed or not grown).
    double factor() const { return automatic_ ? factor_ : 1.0; }

private:
    bool automatic_ = true;
    double reference_ = 0.0; // rms colour value at the start
    double modelTop_ = 0.0;  // the model's colourMax the reference belongs to
    double factor_ = 1.0;    // smoothed growth since the reference
};

} // namespace pl::ui
