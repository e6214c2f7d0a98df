# Are the CRESCENT CFM files (GOCAD TSurf, read in place from ../shared/data/crescent-cfm,
# never copied into the repository) where GEOSHAPING_CFM_DIR says? The tests that read
# them are left out without them, and configuring says which. Included by
# Testing/IO/CMakeLists.txt; runs alone too: cmake -DGEOSHAPING_CFM_DIR=<dir> -P cfm_data.cmake
file(GLOB GEOSHAPING_CFM_FILES "${GEOSHAPING_CFM_DIR}/*.ts")
if(NOT GEOSHAPING_CFM_FILES)
  message(WARNING "GeoShaping: no CRESCENT CFM files (*.ts) in '${GEOSHAPING_CFM_DIR}' "
    "(set GEOSHAPING_CFM_DIR, default ../shared/data/crescent-cfm beside the checkout); "
    "these data tests are left out: IO.CfmFiles/CfmFile.* (one per file), "
    "IO.PvpythonOpensAndSavesTSurf, and Report.Smoke runs without its CFM scene.")
endif()
