# Precompiled headers, shared by kind and applied from one place (docs/performance.md, "The build").
#
# A typical Sortie file spends 1.5-4 s of its compile parsing the same Qt and standard headers
# (<QObject> alone 1.3 s, <QtTest> 3.5 s). Each target compiling its own precompiled header would
# not pay for the ~330 small test programs, so five host targets compile one header each and every
# other target reuses the host of its kind (REUSE_FROM):
#   std    no Qt (the Qt-free codecs: their purity stays enforced, no Qt header reaches them)
#   core   Qt Core, Network, Positioning   (core/, sim/, the command-line programs)
#   gui    core + Gui                      (the rooms with an undo stack, images or paint)
#   quick  gui + Qml, Quick                (ui/, the client)
#   test   core + QtTest                   (tests without Qt Gui)
#   guitest quick + QtTest                 (tests with Qt Gui: QTEST_MAIN makes a QGuiApplication)
#   nettest, guinettest: the same for tests with Qt Network (qtest.h reads QT_NETWORK_LIB)
# The kind is read off the target's links, followed transitively, so a room never receives headers
# of a library it does not link. A reused header must be compiled with the consumer's options: the
# hosts take the same global options, and what differs between targets (their own definitions) is
# never tested by the headers here. GCC's -Winvalid-pch (CMake adds it) reports a header it had to
# refuse; clang refuses loudly.
#
# Left out: the fuzz targets (their own sanitizer flags), targets with a header of their own
# (sortie_sim_hci) and those with the property SORTIE_NO_PCH: the wall probes (each compiles one
# include alone, on purpose) and the generated protobuf code.

option(SORTIE_PCH "Compile with the shared precompiled headers" ON)
option(SORTIE_PCH_VERBOSE "Name each target's precompiled header at configure time" OFF)

set(_sortie_pch_std <algorithm> <array> <chrono> <cmath> <cstdint> <cstdio> <cstdlib> <functional>
    <limits> <map> <memory> <numbers> <optional> <string> <string_view> <utility> <vector>)
set(_sortie_pch_core ${_sortie_pch_std}
    <QtCore/QAbstractListModel> <QtCore/QByteArray> <QtCore/QCoreApplication> <QtCore/QDateTime>
    <QtCore/QDir> <QtCore/QElapsedTimer> <QtCore/QFile> <QtCore/QFileInfo> <QtCore/QHash>
    <QtCore/QList> <QtCore/QLocale> <QtCore/QLoggingCategory> <QtCore/QObject> <QtCore/QPointer>
    <QtCore/QRegularExpression> <QtCore/QSet> <QtCore/QSettings> <QtCore/QString>
    <QtCore/QStringList> <QtCore/QTimer> <QtCore/QUrl> <QtCore/QVariant>
    <QtNetwork/QTcpServer> <QtNetwork/QTcpSocket> <QtPositioning/QGeoCoordinate>)
set(_sortie_pch_gui ${_sortie_pch_core}
    <QtGui/QColor> <QtGui/QGuiApplication> <QtGui/QImage> <QtGui/QPainter> <QtGui/QUndoStack>)
set(_sortie_pch_quick ${_sortie_pch_gui} <QtQml/QQmlEngine> <QtQml/qqmlregistration.h> <QtQuick/QQuickItem> <QtQuick/QQuickPaintedItem>
    <QtQuick/QQuickWindow>)
# <QtTest/QtTest> (64 test files include it) brings the whole of QtCore.
set(_sortie_pch_test ${_sortie_pch_core} <QtTest/QtTest>)
set(_sortie_pch_guitest ${_sortie_pch_quick} <QtTest/QtTest>)

# The Qt modules whose headers each host reads. A host takes their include folders, not their
# links: linking would define QT_<MODULE>_LIB for each, and GCC refuses a header made with a
# definition its consumer lacks. Only the test hosts define the two a precompiled header reads
# (qtest.h tests QT_GUI_LIB and QT_NETWORK_LIB), each exactly as its consumers do.
set(_sortie_pch_modules_std "")
set(_sortie_pch_modules_core Core Network Positioning)
set(_sortie_pch_modules_gui Core Network Positioning Gui)
set(_sortie_pch_modules_quick Core Network Positioning Gui Qml Quick)
set(_sortie_pch_modules_test Core Network Positioning Test)
set(_sortie_pch_modules_nettest Core Network Positioning Test)
set(_sortie_pch_modules_guitest Core Network Positioning Gui Qml Quick Test)
set(_sortie_pch_modules_guinettest Core Network Positioning Gui Qml Quick Test)
set(_sortie_pch_defines_nettest QT_NETWORK_LIB)
set(_sortie_pch_defines_guitest QT_GUI_LIB)
set(_sortie_pch_defines_guinettest QT_GUI_LIB QT_NETWORK_LIB)
set(_sortie_pch_nettest ${_sortie_pch_test})
set(_sortie_pch_guinettest ${_sortie_pch_guitest})
set(_sortie_pch_kinds std core gui quick test nettest guitest guinettest)

# Every library a target links, directly or through others (imported Qt targets included).
function(_sortie_link_closure target out)
  set(seen "")
  set(queue ${target})
  while(queue)
    list(POP_FRONT queue t)
    if(t IN_LIST seen OR NOT TARGET ${t})
      continue()
    endif()
    list(APPEND seen ${t})
    get_target_property(type ${t} TYPE)
    get_target_property(imported ${t} IMPORTED)
    set(libs "")
    if(NOT imported AND NOT type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(direct ${t} LINK_LIBRARIES)
      if(direct)
        list(APPEND libs ${direct})
      endif()
    endif()
    get_target_property(interface ${t} INTERFACE_LINK_LIBRARIES)
    if(interface)
      list(APPEND libs ${interface})
    endif()
    foreach(lib ${libs})
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" lib "${lib}")
      if(lib MATCHES "^[A-Za-z0-9_:.+-]+$" AND NOT lib MATCHES "^::@")
        list(APPEND queue ${lib})
      endif()
    endforeach()
  endwhile()
  set(${out} ${seen} PARENT_SCOPE)
endfunction()

function(_sortie_pch_kind target out)
  _sortie_link_closure(${target} links)
  if(NOT "Qt6::Core" IN_LIST links)
    set(kind std)
  elseif("Qt6::Quick" IN_LIST links OR "Qt6::Qml" IN_LIST links)
    set(kind quick)
  elseif("Qt6::Gui" IN_LIST links)
    set(kind gui)
  else()
    set(kind core)
  endif()
  if("Qt6::Test" IN_LIST links AND NOT kind STREQUAL "std")
    set(kind test)
    if("Qt6::Gui" IN_LIST links)
      set(kind gui${kind})
    endif()
    if("Qt6::Network" IN_LIST links)
      string(REPLACE "test" "nettest" kind ${kind})
    endif()
  endif()
  set(${out} ${kind} PARENT_SCOPE)
endfunction()

function(_sortie_targets_below dir out)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub ${subdirs})
    _sortie_targets_below(${sub} more)
    list(APPEND targets ${more})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

# Call once, at the end of the top-level CMakeLists.txt, when every target exists.
function(sortie_precompile_headers)
  if(NOT SORTIE_PCH)
    return()
  endif()
  set(host_dir ${PROJECT_BINARY_DIR}/pch)
  foreach(kind ${_sortie_pch_kinds})
    set(host sortie_pch_${kind})
    file(CONFIGURE OUTPUT ${host_dir}/${kind}.cpp CONTENT "// The host of the ${kind} precompiled header.\n")
    add_library(${host} OBJECT EXCLUDE_FROM_ALL ${host_dir}/${kind}.cpp)
    set_target_properties(${host} PROPERTIES AUTOMOC OFF AUTOUIC OFF AUTORCC OFF)
    if(_sortie_pch_modules_${kind})
      # What Qt6::Core gives every Qt consumer (Qt6CoreConfigExtras.cmake), but no QT_<MODULE>_LIB.
      target_compile_options(${host} PRIVATE -fPIC)
      target_compile_definitions(${host} PRIVATE $<$<NOT:$<CONFIG:Debug>>:QT_NO_DEBUG>)
      foreach(module ${_sortie_pch_modules_${kind}})
        target_include_directories(${host} SYSTEM PRIVATE
                                   $<TARGET_PROPERTY:Qt6::${module},INTERFACE_INCLUDE_DIRECTORIES>)
      endforeach()
      target_compile_definitions(${host} PRIVATE ${_sortie_pch_defines_${kind}})
    endif()
    target_precompile_headers(${host} PRIVATE ${_sortie_pch_${kind}})
    # clang records the headers' times in the header it writes and refuses it when they differ; a
    # header ccache hands to another clone would be refused for its own file's time.
    if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
      target_compile_options(${host} PRIVATE -Xclang -fno-pch-timestamp)
    endif()
    set(count_${kind} 0)
  endforeach()

  _sortie_targets_below(${PROJECT_SOURCE_DIR} targets)
  foreach(target ${targets})
    get_target_property(type ${target} TYPE)
    if(NOT type MATCHES "^(STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$"
       OR target MATCHES "^(sortie_pch_|fuzz_)")
      continue()
    endif()
    get_target_property(own ${target} PRECOMPILE_HEADERS)
    get_target_property(reused ${target} PRECOMPILE_HEADERS_REUSE_FROM)
    get_target_property(opted_out ${target} SORTIE_NO_PCH)
    if(own OR reused OR opted_out)
      continue()
    endif()
    _sortie_pch_kind(${target} kind)
    if(SORTIE_PCH_VERBOSE)
      message(STATUS "  ${target}: ${kind}")
    endif()
    set_target_properties(${target} PROPERTIES PRECOMPILE_HEADERS_REUSE_FROM sortie_pch_${kind})
    add_dependencies(${target} sortie_pch_${kind})
    math(EXPR count_${kind} "${count_${kind}} + 1")
  endforeach()
  set(counts "")
  foreach(kind ${_sortie_pch_kinds})
    string(APPEND counts " ${kind} ${count_${kind}}")
  endforeach()
  message(STATUS "Precompiled headers, targets by kind:${counts}")
endfunction()
