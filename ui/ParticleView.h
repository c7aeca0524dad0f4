// Draws the gas: disks coloured by speed with the thermal palette, the box, obstacles and the piston.
// It only draws; the controller owns the model. (The GL viewport that renders straight from the
// particle buffer replaces it with the GPU backend.)
#pragma once

#include <QWidget>

namespace pl {
class MdModel;
}

namespace pl::ui {

class SimulationController;

class ParticleView : public QWidget {
    Q_OBJECT
public:
    explicit ParticleView(SimulationController* controller, QWidget* parent = nullptr);
    QSize sizeHint() const override { return {800, 800}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    void rescaleColours();

    SimulationController* controller_;
    double colourSpeedMax_ = 2.8; // the seed's V_COLOR_MAX for speed-1 disks: 2.8 × the initial rms speed
};

} // namespace pl::ui
