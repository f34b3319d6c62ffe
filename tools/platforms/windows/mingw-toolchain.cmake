# Cross-compiling for 64-bit Windows with Debian's MinGW-w64 (the posix threads flavour), for the
# Windows smoke test (tools/platforms/windows/cross_build.sh). WB_WIN_PREFIX: where the Windows builds of the
# dependencies are installed.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)
set(CMAKE_AR /usr/bin/x86_64-w64-mingw32-ar CACHE FILEPATH "")
set(CMAKE_RANLIB /usr/bin/x86_64-w64-mingw32-ranlib CACHE FILEPATH "")
if(NOT WB_WIN_PREFIX)
  set(WB_WIN_PREFIX "$ENV{WB_WIN_PREFIX}")
endif()
set(WB_WIN_PREFIX "${WB_WIN_PREFIX}" CACHE PATH "the Windows builds of the dependencies")
# Libraries and headers from the MinGW sysroot and that prefix only; programs from the host.
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32 ${WB_WIN_PREFIX})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# One .exe with no MinGW runtime DLLs beside it.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static -static-libgcc -static-libstdc++")
set(CMAKE_CROSSCOMPILING_EMULATOR /usr/lib/wine/wine64)
# pkg-config (imgui.pc) sees the Windows prefix only, never the host's.
set(ENV{PKG_CONFIG_LIBDIR} "${WB_WIN_PREFIX}/lib/pkgconfig")
set(ENV{PKG_CONFIG_PATH} "")
