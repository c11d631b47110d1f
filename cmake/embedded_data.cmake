# The committed data compiled into the library (the native build and the
# WebAssembly build, web/CMakeLists.txt): sets AAPAT_GENERATED, AAPAT_DATA_CPP,
# AAPAT_PATTERNS_CPP and AAPAT_SEQUENCES_CPP, and writes aapat/version.h.
# AAPAT_SOURCE_ROOT: the repository's root.
# The reference data ships inside the library, so aapat works from any folder.
set(AAPAT_GENERATED ${CMAKE_BINARY_DIR}/generated)
set(AAPAT_DATA_CPP ${AAPAT_GENERATED}/embedded_data.cpp)
file(READ ${AAPAT_SOURCE_ROOT}/data/acuity-laine-aila.csv AAPAT_ACUITY_CSV)
file(READ ${AAPAT_SOURCE_ROOT}/data/msaa-standard-positions.csv AAPAT_MSAA_CSV)
configure_file(${AAPAT_SOURCE_ROOT}/data/embedded_data.cpp.in ${AAPAT_DATA_CPP} @ONLY)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
  ${AAPAT_SOURCE_ROOT}/data/acuity-laine-aila.csv ${AAPAT_SOURCE_ROOT}/data/msaa-standard-positions.csv)
# Committed data embedded in the binary, one raw string per file by name:
# the aapat catalog (data/patterns/*.json, scripts/make-catalog.sh) in the io
# layer, the optimized sequences (data/sequences/*.json,
# scripts/make-sequences.sh) in the temporal layer.
function(aapat_embed folder symbol out)
  file(GLOB files ${AAPAT_SOURCE_ROOT}/data/${folder}/*.json)
  list(SORT files)
  set(AAPAT_EMBED_ENTRIES "")
  foreach(file ${files})
    get_filename_component(name ${file} NAME_WLE)
    file(READ ${file} text)
    string(APPEND AAPAT_EMBED_ENTRIES "    {\"${name}\", R\"aapat_json(${text})aapat_json\"},\n")
  endforeach()
  set(AAPAT_EMBED_FOLDER ${folder})
  set(AAPAT_EMBED_SYMBOL ${symbol})
  configure_file(${AAPAT_SOURCE_ROOT}/data/embedded_files.cpp.in ${out} @ONLY)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${AAPAT_SOURCE_ROOT}/data/${folder}
    ${files})
endfunction()
set(AAPAT_PATTERNS_CPP ${AAPAT_GENERATED}/embedded_patterns.cpp)
aapat_embed(patterns kAapatPatterns ${AAPAT_PATTERNS_CPP})
set(AAPAT_SEQUENCES_CPP ${AAPAT_GENERATED}/embedded_sequences.cpp)
aapat_embed(sequences kAapatSequences ${AAPAT_SEQUENCES_CPP})
# The version, defined once (project() in the root CMakeLists.txt), for the CLI, the Python module,
# pkg-config and the web page.
configure_file(${AAPAT_SOURCE_ROOT}/src/aapat/version.h.in ${AAPAT_GENERATED}/aapat/version.h @ONLY)
