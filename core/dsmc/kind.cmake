# The DSMC cell (docs/dsmc.md): collected by core/CMakeLists.txt like every folder with a kind.cmake. The
# registration function is defined in DsmcRegistration.cpp and joins the catalog in the order of KIND_ORDER.
set(KIND_ORDER 2)
set(KIND_REGISTRATION dsmcRegistration)
set(KIND_SOURCES
  DsmcCollisionModel.cpp DsmcInitialState.cpp DsmcModel.cpp DsmcObservables.cpp DsmcParams.cpp
  DsmcRegistration.cpp DsmcTheoryRows.cpp MolecularParams.cpp DsmcSnapshot.cpp DsmcSweep.cpp DsmcTheory.cpp)
