# Every dependency comes from Debian 12. A missing one stops configuration with the name of
# the package that provides it, so "apt-get install <that>" is the whole fix.
include_guard(GLOBAL)

function(lacrima_missing what debian_package)
  message(FATAL_ERROR
    "Lacrima needs ${what}, which was not found.\n"
    "Install it with:  apt-get install ${debian_package}\n"
    "(or run 'bash packaging/lacrima.sh test', which installs everything in packaging/debian-packages.txt)")
endfunction()

find_package(Qt6 6.4 QUIET COMPONENTS Core Gui Widgets Test Network)
if(NOT Qt6_FOUND OR NOT TARGET Qt6::Widgets OR NOT TARGET Qt6::Test OR NOT TARGET Qt6::Network)
  lacrima_missing("Qt 6 (Core, Gui, Widgets, Test, Network)" "qt6-base-dev")
endif()
set(CMAKE_AUTOMOC ON)

find_package(Eigen3 3.4 QUIET NO_MODULE)
if(NOT TARGET Eigen3::Eigen)
  lacrima_missing("Eigen 3.4" "libeigen3-dev")
endif()

# Only OgreMain: the scene uses GLSL programs of its own, not the RT Shader System or Bites.
find_package(OGRE 1.12 QUIET)
if(NOT OGRE_FOUND OR NOT TARGET OgreMain)
  lacrima_missing("OGRE 1.12" "libogre-1.12-dev")
endif()

find_package(assimp QUIET)
if(NOT TARGET assimp::assimp)
  lacrima_missing("assimp 5" "libassimp-dev")
endif()
# Debian's assimp targets name zlib's development library without depending on its package;
# without it the failure would only show at link time.
find_package(ZLIB QUIET)
if(NOT ZLIB_FOUND)
  lacrima_missing("zlib's development files (linked by assimp's CMake package)" "zlib1g-dev")
endif()

# Debian builds tinygltf as a shared library with its JSON and image code inside, so neither
# nlohmann-json3-dev nor libstb-dev is needed here.
find_package(TinyGLTF 2.7 QUIET CONFIG)
if(NOT TARGET TinyGLTF::TinyGLTF)
  lacrima_missing("tinygltf 2.7 (the .glb writer)" "libtinygltf-dev")
endif()

find_package(PkgConfig QUIET)
if(NOT PKG_CONFIG_FOUND)
  lacrima_missing("pkg-config (to find ODE)" "pkg-config")
endif()
pkg_check_modules(ODE QUIET IMPORTED_TARGET ode>=0.16)
if(NOT ODE_FOUND)
  lacrima_missing("ODE 0.16" "libode-dev")
endif()
# FFmpeg's libraries write the videos (lacrima_export): in the process, not by running a program.
pkg_check_modules(FFMPEG QUIET IMPORTED_TARGET libavformat libavcodec libswscale libavutil)
if(NOT FFMPEG_FOUND)
  lacrima_missing("FFmpeg's libraries (the video export)"
                  "libavformat-dev libavcodec-dev libswscale-dev libavutil-dev")
endif()
