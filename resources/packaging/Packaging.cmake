# The Debian package, made by CPack from the install rules (cpack -G DEB in the build folder):
# particlelab_<version>_amd64.deb. .ci/package.sh builds it and checks it with lintian and in a clean root.
include(GNUInstallDirs)
set(packaging_dir ${PROJECT_SOURCE_DIR}/resources/packaging)

# What Debian asks of every package beside its programs: the copyright file, and the changelog (of a
# native package, as this one is: no Debian revision) compressed without a time stamp.
set(package_doc_dir ${CMAKE_INSTALL_DATADIR}/doc/particlelab)
install(FILES ${packaging_dir}/copyright DESTINATION ${package_doc_dir})
find_program(GZIP gzip REQUIRED)
add_custom_command(
  OUTPUT ${CMAKE_BINARY_DIR}/packaging/changelog.gz
  COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/packaging
  COMMAND ${CMAKE_COMMAND} -E copy ${packaging_dir}/changelog ${CMAKE_BINARY_DIR}/packaging/changelog
  COMMAND ${GZIP} -9nf ${CMAKE_BINARY_DIR}/packaging/changelog
  DEPENDS ${packaging_dir}/changelog
  COMMENT "Debian changelog"
  VERBATIM)
add_custom_target(particlelab_changelog ALL DEPENDS ${CMAKE_BINARY_DIR}/packaging/changelog.gz)
install(FILES ${CMAKE_BINARY_DIR}/packaging/changelog.gz DESTINATION ${package_doc_dir})

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME particlelab)
set(CPACK_PACKAGE_VENDOR "The ParticleLab maintainers")
set(CPACK_PACKAGE_CONTACT "ParticleLab maintainers <maintainers@users.noreply.h-seed-39cf63b6.example>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "interactive physics lab of gases, rarefied flows and fluids")
# The long description, in lines that fit an 80-column terminal (Debian Policy 3.4.1, as lintian checks).
set(CPACK_PACKAGE_DESCRIPTION
    "ParticleLab shows a 2D gas of disks whose speeds relax to the Maxwell-Boltzmann
distribution, rarefied gases simulated with Bird's DSMC method, a wind tunnel
and position-based fluids, as particles you can drag, heat and measure, with
live plots and every parameter open to change.

The package holds the desktop application (particlelab), the headless runner
that writes an experiment's observables as CSV (particlelab-cli), the GPU
benchmark (particlelab-bench), the built-in presets as example files, and man
pages. It runs on Mesa's software renderer where there is no GPU.")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # particlelab_<version>_<architecture>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_COMPRESSION_TYPE xz)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
# Libraries come from dpkg-shlibdeps; these are loaded at run time and no link shows them: libepoxy opens
# the EGL and GL dispatchers (libegl1, libgl1) itself, Mesa's drivers (llvmpipe where there is no GPU)
# serve GLX windows and headless EGL contexts, and Qt loads its platform plugins and themes. Qt's Wayland plugin and Qt's own strings in other languages are recommended; LAMMPS
# and Open MPI run the scale-out commands (docs/scale-out.md). FFmpeg's libraries (recording: libavformat,
# libavcodec, libswscale, libavutil) are linked, so dpkg-shlibdeps lists them; libavcodec's package
# brings the encoders it was built with (libx264, libvpx), and the CLI's offscreen platform is Qt's own.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl1, libgl1, libgl1-mesa-dri, libglx-mesa0, libegl-mesa0, qt6-qpa-plugins")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-wayland, qt6-translations-l10n")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "lammps, openmpi-bin")
# The programs are stripped, with the compiler's notes (app/CMakeLists.txt). There is no separate
# debug-symbols package: CPack makes one only for a component build (CPACK_DEBIAN_DEBUGINFO_PACKAGE), and
# a developer debugs from the source build.
set(CPACK_STRIP_FILES ON)
# lintian's remaining tags are of level info, none a warning:
# - hardening-no-fortify-functions, hardening-no-bindnow: the package is built with the project's own
#   flags (Release, -O3; Debian's GCC makes PIE and RELRO by default), not dpkg-buildflags, so that the
#   packaged programs are the ones the tests and benchmarks measure;
# - spelling-error-in-binary "lengH": bytes of machine code that read as a word, not a text.
include(CPack)
