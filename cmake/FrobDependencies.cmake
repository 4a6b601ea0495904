# Every dependency comes from a Debian 12 package (cmake/install-deps.sh); nothing is downloaded.
find_package(PkgConfig REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(box2d 2.4 REQUIRED CONFIG)
find_package(assimp REQUIRED CONFIG)
find_package(tomlplusplus 3 REQUIRED CONFIG)
find_package(CLI11 2 REQUIRED CONFIG)
find_package(nlohmann_json 3 REQUIRED CONFIG)
find_package(PNG REQUIRED)
find_package(ZLIB REQUIRED)                                  # the run viewer page's data
find_package(Freetype REQUIRED)
find_package(Threads REQUIRED)
pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)
pkg_check_modules(LIBAV REQUIRED IMPORTED_TARGET libavcodec libavformat libavutil libswscale)
pkg_check_modules(LIBZIP REQUIRED IMPORTED_TARGET libzip)  # the Gradescope autograder zip
find_package(OpenSSL 3 REQUIRED COMPONENTS Crypto)           # the signatures of graded runs' wheel logs

# The font the renderer draws text with (Debian: fonts-dejavu-core).
find_file(FROB_FONT_FILE DejaVuSans.ttf PATHS /usr/share/fonts/truetype/dejavu REQUIRED)
find_file(FROB_MONO_FONT_FILE DejaVuSansMono.ttf PATHS /usr/share/fonts/truetype/dejavu REQUIRED)
