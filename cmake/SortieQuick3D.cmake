# Qt Quick 3D for the 3D view (ui/view3d). Debian 12's qt6-quick3d-dev asks CMake for Qt6ShaderTools
# (through Qt6Quick3DRuntimeRender) without depending on qt6-shadertools-dev, so on a machine without
# that package find_package(Qt6 COMPONENTS Quick3D) fails although the library, its headers and its
# QML module are there. Then Qt6::Quick3D is made here from them (what the view links: the library,
# its headers, and its type descriptions for qmltyperegistrar); the shader tools are not needed to
# build, since the view uses Qt Quick 3D's own materials.
find_package(Qt6 6.4 QUIET COMPONENTS Quick3D)
if(NOT TARGET Qt6::Quick3D)
  find_package(Qt6 6.4 REQUIRED COMPONENTS Quick)
  get_target_property(_sortie_quick_includes Qt6::Quick INTERFACE_INCLUDE_DIRECTORIES)
  find_library(SORTIE_QT6QUICK3D_LIBRARY NAMES Qt6Quick3D REQUIRED)
  find_path(SORTIE_QT6QUICK3D_INCLUDE NAMES QtQuick3D/QQuick3DGeometry PATHS ${_sortie_quick_includes} REQUIRED)
  add_library(Qt6::Quick3D SHARED IMPORTED GLOBAL)
  set_target_properties(Qt6::Quick3D PROPERTIES
      IMPORTED_LOCATION ${SORTIE_QT6QUICK3D_LIBRARY}
      INTERFACE_INCLUDE_DIRECTORIES "${SORTIE_QT6QUICK3D_INCLUDE};${SORTIE_QT6QUICK3D_INCLUDE}/QtQuick3D"
      INTERFACE_LINK_LIBRARIES Qt6::Quick)
  find_file(SORTIE_QT6QUICK3D_METATYPES NAMES qt6quick3d_none_metatypes.json qt6quick3d_release_metatypes.json
            PATH_SUFFIXES metatypes qt6/metatypes)
  message(STATUS "Qt Quick 3D: ${SORTIE_QT6QUICK3D_LIBRARY} (qt6-shadertools-dev missing: Qt6::Quick3D made by cmake/SortieQuick3D.cmake)")
endif()
