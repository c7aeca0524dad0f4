# The gas (docs/gas.md): collected by core/CMakeLists.txt like every folder with a kind.cmake. The
# registration function is defined in GasRegistration.cpp and joins the catalog in the order of KIND_ORDER.
set(KIND_ORDER 1)
set(KIND_REGISTRATION gasRegistration)
set(KIND_SOURCES
  GasBenchmarkScale.cpp GasBoundaries.cpp GasForces.cpp GasInitialState.cpp GasIntegratorTable.cpp GasIntegrators.cpp GasModel.cpp
  GasObservables.cpp GasParams.cpp GasRegistration.cpp GasTheoryRows.cpp GasScene.cpp GasSnapshot.cpp GasSpawner.cpp
  GasStability.cpp GasState.cpp MethodSweep.cpp StabilityMap.cpp TimeReversal.cpp)
