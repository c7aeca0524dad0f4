# The desktop application's place on a Linux desktop, by the freedesktop conventions (included by
# app/CMakeLists.txt): the launcher, the icon in the hicolor sizes and as SVG, the file types
# (shared-mime-info) that open in it, and the AppStream metadata software centres show.
set(desktop_dir ${PROJECT_SOURCE_DIR}/resources/desktop)
install(FILES ${desktop_dir}/particlelab.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${desktop_dir}/particlelab.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages)

# The icon: the SVG as it is, and PNGs rendered from it at build time for the sizes hicolor lists.
set(icon_svg ${PROJECT_SOURCE_DIR}/resources/icons/particlelab.svg)
install(FILES ${icon_svg} DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
find_program(RSVG_CONVERT rsvg-convert)
if(RSVG_CONVERT)
  set(icon_pngs)
  foreach(size 16 22 24 32 48 64 128 256 512)
    set(png_dir ${CMAKE_CURRENT_BINARY_DIR}/icons/${size}x${size})
    add_custom_command(
      OUTPUT ${png_dir}/particlelab.png
      COMMAND ${CMAKE_COMMAND} -E make_directory ${png_dir}
      COMMAND ${RSVG_CONVERT} --width=${size} --height=${size} --output=${png_dir}/particlelab.png ${icon_svg}
      DEPENDS ${icon_svg}
      COMMENT "Icon particlelab.png, ${size}×${size}"
      VERBATIM)
    install(FILES ${png_dir}/particlelab.png DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/${size}x${size}/apps)
    list(APPEND icon_pngs ${png_dir}/particlelab.png)
  endforeach()
  add_custom_target(particlelab_icons ALL DEPENDS ${icon_pngs})
else()
  message(WARNING "rsvg-convert not found: the icon is installed as SVG only (.ci/install-deps.sh installs "
                  "librsvg2-bin)")
endif()

# AppStream: the component's id is reverse DNS of the project's home; its launcher is particlelab.desktop.
# The screenshots are the PNGs in docs/screenshots/, served from the project's repository.
set(PARTICLELAB_APPSTREAM_ID io.github.particlelab.particlelab)
set(PARTICLELAB_SCREENSHOT_URL "https://raw.githubusercontent.com/particlelab/particlelab/main/docs/screenshots")
set(metainfo ${CMAKE_CURRENT_BINARY_DIR}/${PARTICLELAB_APPSTREAM_ID}.metainfo.xml)
configure_file(${desktop_dir}/particlelab.metainfo.xml.in ${metainfo} @ONLY)
install(FILES ${metainfo} DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
