// The report's key readouts beside the theory the model is checked against, each with a verdict: the
// rows the model's kind computes in core (ModelDescriptor::theoryRows; the gas's speeds against
// Maxwell–Boltzmann and its kT·A against the adiabat, the DSMC cell's moments against BKW, the tunnel's
// drag against the free-molecular value, the fluid's density error and dam-break front), as report rows.
#pragma once

#include "LabReport.h"

namespace pl {
class Model;
class TimeSeries;
} // namespace pl

namespace pl::ui {

// The rows for `model` at the end of its run; `series` is what the app or the CLI sampled of it. Empty
// where no theory applies.
std::vector<ReportRow> theoryReadouts(const Model& model, const TimeSeries& series);

} // namespace pl::ui
