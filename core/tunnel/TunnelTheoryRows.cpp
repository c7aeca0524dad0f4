// The wind tunnel's report row (ModelDescriptor::theoryRows): the drag of body 0 against a diffuse
// cylinder's in free-molecular flow. A disc centred on a specular bottom or top side is half a cylinder
// (the side is its symmetry plane), so the theory is halved.
#include "TunnelModel.h"
#include "TunnelTheory.h"
#include "common/TheoryRows.h"

#include <cmath>

namespace pl {

namespace {
constexpr double kFreeMolecularKn = 10.0; // Kn from which a body sees free-molecular flow
} // namespace

std::vector<TheoryRow> tunnelTheoryRows(const Model& model, const TimeSeries& series) {
    const auto* tunnel = dynamic_cast<const TunnelModel*>(&model); // the CPU model or its GPU twin
    if (!tunnel || tunnel->obstacles().empty()) return {};
    const TunnelParams& p = tunnel->parameters();
    const Obstacle& body = tunnel->obstacles().front();
    if (body.shape != Obstacle::Shape::Disc || p.surface != TunnelSurface::Diffuse || !(p.streamSpeed > 0))
        return {};
    const auto onSymmetryPlane = [&](double sideY, TunnelBoundary side) {
        return side == TunnelBoundary::Specular && std::abs(body.y - sideY) <= 1e-9 * p.boxHeight;
    };
    const bool half = onSymmetryPlane(0.0, p.bottom) || onSymmetryPlane(p.boxHeight, p.top);
    const double theory = (half ? 0.5 : 1.0) * tunnel_theory::freeMolecularCylinderDrag(
                                                   p.streamDensity, p.streamTemperature, p.mass(),
                                                   p.streamSpeed, body.radius, p.bodyTemperature);
    const SeriesColumns columns(series);
    const bool averaged = columns.last("sampled_steps") > 0;
    const double drag = averaged ? columns.last("drag_avg") : columns.last("drag");
    if (!std::isfinite(drag)) return {};
    const double kn = tunnel->knudsenNumber();
    const std::string applies =
        kn >= kFreeMolecularKn
            ? "Kn = " + theoryNumber(kn) + ": free-molecular flow, where the drag tends to this value"
            : "Kn = " + theoryNumber(kn) +
                  ": collisions shield the body, so this is the rarefied limit, not a "
                  "prediction";
    return {{averaged ? "Drag of the body, averaged over the fields window" : "Drag of the body, last step",
             theoryNumber(drag), "N/m",
             std::string("free-molecular value for a diffuse ") + (half ? "half " : "") + "cylinder " +
                 theoryNumber(theory) + " N/m (ratio " + theoryNumber(drag / theory) + "); " + applies}};
}

} // namespace pl
