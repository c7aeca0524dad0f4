// Physical constants in SI units, one definition for every kind that works in the SI (the DSMC cell,
// the wind tunnel, the SPARTA decks). The gas and the fluid work in reduced units and use none.
#pragma once

namespace pl {

inline constexpr double kBoltzmann = 1.380649e-23;       // k_B [J/K], exact in the SI since 2019
inline constexpr double kAtomicMass = 1.66053906660e-27; // atomic mass constant m_u [kg], CODATA 2018

} // namespace pl
