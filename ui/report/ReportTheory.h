// The report's key readouts beside the theory the model is checked against, each with a verdict, for the
// kinds where one applies: the gas's speeds against Maxwell–Boltzmann (KS distance against the 1 %
// critical value, and the maximum-likelihood fit) and its kT·A against the adiabat once the piston has
// moved, the DSMC cell's moments against the exact BKW solution and its kurtosis against a Maxwellian's,
// the wind tunnel's drag against the free-molecular value of a diffuse cylinder, and the fluid's density
// error against the methods lab's tolerance and its dam-break front against Ritter's bound. Every formula
// is the core's (common/Statistics.h, dsmc/DsmcTheory.h, tunnel/TunnelTheory.h, fluid/FluidSweep.h);
// this file only reads and words them.
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
