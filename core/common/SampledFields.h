// Fields a model samples on a grid of cells (the wind tunnel's density, velocity, temperature, Mach):
// what the viewport's colour map, its click probe, the profile dock and the CLI's --fields read. A model
// offers it through Model::sampledFields(); models without sampled fields return nullptr.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pl {

// One field the model can show, e.g. {"mach", "Mach number", ""}.
struct FieldChoice {
    std::string name;  // stable key: "n", "speed", "T", "mach", ...
    std::string label; // legend title
    std::string unit;  // e.g. "m⁻³"; empty when dimensionless
};

// A field's cell averages over the current sampling window. Cell (i, j) spans
// [left + i·dx, left + (i+1)·dx] × [bottom + j·dy, bottom + (j+1)·dy]; values are row-major (j·nx + i)
// and NaN where a cell holds no sample (inside a body, or never visited).
struct FieldGrid {
    FieldChoice choice;
    int nx = 0, ny = 0;
    double left = 0, bottom = 0, right = 1, top = 1; // [m]
    std::vector<double> values;

    double dx() const { return (right - left) / nx; }
    double dy() const { return (top - bottom) / ny; }
    // The value of the cell holding (x, y); NaN outside the grid.
    double at(double x, double y) const;
};

// One value at a point, for the click probe and the profile dock.
struct FieldValue {
    FieldChoice choice;
    double value = 0.0;
};

// The values along a straight line (a stagnation line the user draws).
struct FieldProfile {
    FieldChoice choice;
    std::vector<double> distance; // from the line's start [m]
    std::vector<double> values;   // NaN where no sample
};

class SampledFields {
public:
    virtual ~SampledFields() = default;

    virtual std::vector<FieldChoice> fieldChoices() const = 0;
    // Throws std::invalid_argument for a name fieldChoices() does not list.
    virtual FieldGrid field(const std::string& name) const = 0;
    // Every field at the cell holding (x, y); empty outside the domain.
    virtual std::vector<FieldValue> probe(double x, double y) const = 0;
    // Steps in the current sampling window (restarted whenever the user changes something).
    virtual std::int64_t sampledSteps() const = 0;
    // Writes the fields as CSV: i,j,x,y,n,ux,uy,T,Tx,Ty,mach (cell centres; SI units).
    virtual void writeFieldsCsv(std::ostream& out) const = 0;
};

// `samples` values of grid along (x0, y0) → (x1, y1), ends included (samples ≥ 2).
FieldProfile profileAlong(const FieldGrid& grid, double x0, double y0, double x1, double y1, int samples);

} // namespace pl
