# Writes OUT: a C++ file with assets/viewer.js and assets/report.css as strings, so the report
# page carries its script and style and needs no installed files.
file(READ "${ASSETS}/viewer.js" viewer)
file(READ "${ASSETS}/report.css" style)
set(body "// Generated from output/report/assets by embed_assets.cmake; do not edit.\n")
string(APPEND body "#include \"output/report/report_assets.h\"\n\nnamespace sled::report {\n\n")
string(APPEND body "std::string_view ViewerScript() {\n  return R\"sledasset(${viewer})sledasset\";\n}\n\n")
string(APPEND body "std::string_view PageStyle() {\n  return R\"sledasset(${style})sledasset\";\n}\n\n")
string(APPEND body "}  // namespace sled::report\n")
file(WRITE "${OUT}.tmp" "${body}")
configure_file("${OUT}.tmp" "${OUT}" COPYONLY)
