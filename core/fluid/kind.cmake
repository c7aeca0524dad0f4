# The fluid (docs/fluid.md): collected by core/CMakeLists.txt like every folder with a kind.cmake. The
# registration function is defined in FluidRegistration.cpp and joins the catalog in the order of KIND_ORDER.
set(KIND_ORDER 3)
set(KIND_REGISTRATION fluidRegistration)
set(KIND_SOURCES
  FluidBenchmarkScale.cpp FluidSweep.cpp FluidModel.cpp FluidNeighbours.cpp FluidObservables.cpp FluidParams.cpp
  FluidRegistration.cpp FluidTheoryRows.cpp FluidScene.cpp FluidSnapshot.cpp FluidSolver.cpp FluidLambdaPass.cpp FluidRowScan.cpp)
# The AVX-512 builds may use FMA instructions, which would round a product and a sum once where the SSE2
# build rounds twice: no contraction keeps every build's bits and decisions the same (FluidLambdaPass.h,
# FluidRowScan.h).
set_source_files_properties(${CMAKE_CURRENT_LIST_DIR}/FluidLambdaPass.cpp ${CMAKE_CURRENT_LIST_DIR}/FluidRowScan.cpp
                            PROPERTIES COMPILE_OPTIONS -ffp-contract=off)
