# Certificate writer (engine side). The checker below shares no code with it.
find_package(OpenSSL REQUIRED)
find_package(zstd REQUIRED)  # Debian: libzstd-dev
add_library(aspects_cert_writer STATIC ${PROJECT_SOURCE_DIR}/certificates/certificate_writer.cpp
            ${PROJECT_SOURCE_DIR}/certificates/compact_records.cpp
            ${PROJECT_SOURCE_DIR}/certificates/count_certificate.cpp
            ${PROJECT_SOURCE_DIR}/certificates/compressed_output.cpp
            ${PROJECT_SOURCE_DIR}/certificates/hashing_output.cpp)
target_include_directories(aspects_cert_writer PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/certificates>)
target_link_libraries(aspects_cert_writer PUBLIC aspects_engine OpenSSL::Crypto PRIVATE zstd::libzstd_shared)
aspects_use_version(aspects_cert_writer)
