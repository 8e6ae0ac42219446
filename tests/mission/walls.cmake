# The walls between core/mission's rooms (core/mission/CMakeLists.txt), shown by the compiler: each
# probe is one source that includes a header of a room above (or beside) the room under test, built
# with exactly that room's include directories and links. The test passes only when the compiler
# says the header is not there; any other outcome (it compiles, or fails for another reason) fails.
# The probes are excluded from the build; each test builds its own, one at a time.

find_package(ZLIB REQUIRED)  # the rooms' imported link targets are visible per directory

# sortie_mission_probe(<wall|open> <room> <header>): `wall` passes when the header is not found from
# the room; `open` (a control) when it compiles there.
function(sortie_mission_probe kind room header)
  string(MAKE_C_IDENTIFIER "mission_${kind}_${room}_${header}" probe)
  set(source ${CMAKE_CURRENT_BINARY_DIR}/walls/${probe}.cpp)
  file(CONFIGURE OUTPUT ${source} CONTENT "#include \"${header}\"\n" @ONLY)
  add_library(${probe} OBJECT EXCLUDE_FROM_ALL ${source})
  set_target_properties(${probe} PROPERTIES SORTIE_NO_PCH ON)  # a probe compiles its one include alone
  set_target_properties(${probe} PROPERTIES AUTOMOC OFF AUTOUIC OFF AUTORCC OFF)
  get_target_property(room_libs sortie_mission_${room} LINK_LIBRARIES)  # PRIVATE ones too
  target_include_directories(${probe} PRIVATE ${PROJECT_SOURCE_DIR}/core/mission/${room})
  target_link_libraries(${probe} PRIVATE ${room_libs})
  add_test(NAME ${probe} COMMAND ${CMAKE_COMMAND} --build ${PROJECT_BINARY_DIR} --target ${probe})
  set_tests_properties(${probe} PROPERTIES LABELS "unit;walls" TIMEOUT 300 RESOURCE_LOCK build_tree_probes)
  if(kind STREQUAL "wall")
    string(REPLACE "." "\\." header_regex "${header}")
    set_tests_properties(${probe} PROPERTIES
      PASS_REGULAR_EXPRESSION "(${header_regex}: No such file|'${header_regex}' file not found)")
  endif()
endfunction()

# geo: positions only.
sortie_mission_probe(wall geo Route.h)
sortie_mission_probe(wall geo Domain.pb.h)
# model: plain values. No planner, no wire type (the HCI origin is hci's), no editor.
sortie_mission_probe(open model GeoPoint.h)
sortie_mission_probe(wall model SegmentPlanner.h)
sortie_mission_probe(wall model HciOrigin.h)
sortie_mission_probe(wall model RouteModel.h)
# segments: planners on the model.
sortie_mission_probe(open segments Route.h)
sortie_mission_probe(wall segments RouteValidator.h)
sortie_mission_probe(wall segments HciOrigin.h)
sortie_mission_probe(wall segments Domain.pb.h)
# timing: the time model, on the flown path; not statistics, validation, the editor or the wire.
sortie_mission_probe(open timing FlightPath.h)
sortie_mission_probe(wall timing RouteStatistics.h)
sortie_mission_probe(wall timing RouteModel.h)
sortie_mission_probe(wall timing HciOrigin.h)
sortie_mission_probe(wall timing SortieFormat.h)
# analysis: statistics and validation; it does not know the editor's model.
sortie_mission_probe(open analysis ScanPlanCache.h)
sortie_mission_probe(open analysis RouteTiming.h)
sortie_mission_probe(wall analysis RouteModel.h)
sortie_mission_probe(wall analysis HciRouteMapper.h)
sortie_mission_probe(wall analysis Domain.pb.h)
# edit: the undoable model; no wire, no files.
sortie_mission_probe(open edit RouteValidator.h)
sortie_mission_probe(wall edit HciOrigin.h)
sortie_mission_probe(wall edit SortieFormat.h)
sortie_mission_probe(wall edit Domain.pb.h)
# hci: the wire, on the model and the planners; not the editor, the analysis or the files.
sortie_mission_probe(open hci Domain.pb.h)
sortie_mission_probe(wall hci RouteModel.h)
sortie_mission_probe(wall hci RouteValidator.h)
sortie_mission_probe(wall hci SortieFormat.h)
# formats: files, on analysis and hci; not the editor.
sortie_mission_probe(open formats HciOrigin.h)
sortie_mission_probe(wall formats RouteModel.h)
