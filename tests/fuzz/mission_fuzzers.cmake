# Mission importers under libFuzzer: every input must be either read or refused with an error,
# never crash, and what is read must write and read back. Seeds: tests/data/samples/qgc.
foreach(name sortie_reader qgc_plan_reader wpl_reader kml_reader hci_route)
  add_executable(fuzz_${name} ${CMAKE_CURRENT_LIST_DIR}/fuzz_${name}.cpp)
  target_link_libraries(fuzz_${name} PRIVATE sortie_mission)
  target_compile_options(fuzz_${name} PRIVATE -fsanitize=fuzzer)
  target_link_options(fuzz_${name} PRIVATE -fsanitize=fuzzer)
endforeach()
