// The floor for `cgtmo --version`'s start-up: a program that links only OpenImageIO and
// OpenColorIO and prints their versions, so both libraries (and everything they load) are really
// loaded and initialised. bench/startup_bench.cpp runs it beside cgtmo.
#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/imageio.h>

#include <cstdio>

int main() {
  const int v = OIIO::openimageio_version();
  std::printf("minimal_oiio_ocio (OpenImageIO %d.%d, OpenColorIO %s)\n", v / 10000, v / 100 % 100,
              OCIO_NAMESPACE::GetVersion());
  return 0;
}
