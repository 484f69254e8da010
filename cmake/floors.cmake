# nbscope's floors: each folder of src/ is one floor with one CMake target (nbscope_<floor>), and
# the map has to tell the truth (docs/architecture.md, "Floors"): a floor includes only itself and
# the floors its target links, and links only floors below it in NBSCOPE_FLOORS. Configuration
# writes each floor's links and its public headers (the NBSCOPE_PUBLIC_HEADERS its CMakeLists.txt
# lists: what other floors may include, as Box2D keeps include/ apart from src/) into floors_links.cmake; the `nbscope_floors` target (part of `all`)
# runs check_floors.cmake whenever a source changes, so a wrong #include fails the build.

# Bottom to top.
set(NBSCOPE_FLOORS core physics check io render ui app)

# Call after every floor's target exists (the top-level CMakeLists.txt, at its end).
function(nbscope_floors_check)
  set(script "${PROJECT_SOURCE_DIR}/cmake/check_floors.cmake")
  set(links_file "${CMAKE_BINARY_DIR}/floors_links.cmake")
  # Every header of a folder is checked when every floor is built (the window's build); without the
  # window, app's window headers are not compiled, so only the compiled files and what they include.
  set(every_header OFF)
  if(TARGET nbscope_ui)
    set(every_header ON)
  endif()
  set(content "set(FLOORS ${NBSCOPE_FLOORS})\nset(SOURCE_DIR \"${PROJECT_SOURCE_DIR}/src\")\nset(EVERY_HEADER ${every_header})\n")
  set(depends "")
  foreach(floor IN LISTS NBSCOPE_FLOORS)
    if(NOT TARGET nbscope_${floor})
      continue()
    endif()
    get_target_property(links nbscope_${floor} LINK_LIBRARIES)
    set(linked "")
    foreach(link IN LISTS links)
      if(link MATCHES "^nbscope_([a-z]+)$" AND CMAKE_MATCH_1 IN_LIST NBSCOPE_FLOORS)
        list(APPEND linked ${CMAKE_MATCH_1})
      endif()
    endforeach()
    get_target_property(public nbscope_${floor} NBSCOPE_PUBLIC_HEADERS)
    if(NOT public)
      set(public "")  # app: the top floor, nobody includes it
    endif()
    get_target_property(sources nbscope_${floor} SOURCES)
    get_target_property(dir nbscope_${floor} SOURCE_DIR)
    set(files "")
    foreach(source IN LISTS sources)
      if(NOT IS_ABSOLUTE "${source}")
        set(source "${dir}/${source}")
      endif()
      list(APPEND files "${source}")
    endforeach()
    string(APPEND content "set(LINKS_${floor} ${linked})\nset(FILES_${floor} \"${files}\")\nset(PUBLIC_${floor} ${public})\n")
    list(APPEND depends ${files})
  endforeach()
  file(CONFIGURE OUTPUT "${links_file}" CONTENT "${content}")
  # Once now (a wrong link fails the configuration), then on every build that changed a source.
  execute_process(COMMAND ${CMAKE_COMMAND} -DLINKS_FILE=${links_file} -P ${script} RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "nbscope: the floors' includes and links disagree (above)")
  endif()
  file(GLOB headers CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/src/*/*.hpp")
  add_custom_command(OUTPUT "${CMAKE_BINARY_DIR}/floors.stamp"
    COMMAND ${CMAKE_COMMAND} -DLINKS_FILE=${links_file} -P ${script}
    COMMAND ${CMAKE_COMMAND} -E touch "${CMAKE_BINARY_DIR}/floors.stamp"
    DEPENDS ${script} ${links_file} ${depends} ${headers}
    COMMENT "Checking that each floor includes only the floors it links"
    VERBATIM)
  add_custom_target(nbscope_floors ALL DEPENDS "${CMAKE_BINARY_DIR}/floors.stamp")
endfunction()
