# The wind tunnel (docs/wind-tunnel.md): collected by core/CMakeLists.txt like every folder with a kind.cmake. The
# registration function is defined in TunnelRegistration.cpp and joins the catalog in the order of KIND_ORDER.
set(KIND_ORDER 4)
set(KIND_REGISTRATION tunnelRegistration)
set(KIND_SOURCES
  TunnelBenchmarkScale.cpp TunnelCollide.cpp TunnelInflow.cpp TunnelModel.cpp TunnelMove.cpp TunnelObservables.cpp TunnelParams.cpp
  TunnelRegistration.cpp TunnelTheoryRows.cpp TunnelSampler.cpp TunnelSamplerState.cpp TunnelSnapshot.cpp TunnelStepUndo.cpp
  TunnelTheory.cpp)
