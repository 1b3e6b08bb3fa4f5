#!/bin/bash
# Packs what a machine that has only PyTorch (a CUDA LibTorch) needs to build and run `toponav train` there
# -- a lent GPU machine, a cluster node without our Debian packages: the layers that do not use LibTorch,
# prebuilt here; the Debian runtime libraries they load; the Eigen and nlohmann-json headers; and a stand-in
# for OpenCV, whose closure (GDAL, FFmpeg: ~500 MB) does not travel -- pictures and videos abort there with
# a message.  Run from the repository root after `bash scripts/setup.sh`; writes .gpukit/ (~53 MB), then on
# the other machine: scripts/gpu_kit/build_on_gpu.sh (results/learning_gpu/README.md).
set -euo pipefail
B=${BUILD:-build}
K=.gpukit
rm -rf "$K" && mkdir -p "$K/obj" "$K/stage/kitlib" "$K/stage/kitinc"
closure() {  # the shared libraries a library loads, without the C and C++ runtimes every Linux has
  for l in "$@"; do
    p=$(ldconfig -p | awk -v l="$l" '$1 == l {print $NF; exit}')
    [ -n "$p" ] || { echo "make_kit: $l is not installed (run scripts/setup.sh)" >&2; exit 1; }
    echo "$p"; ldd "$p" | awk '/=>/ {print $3}'
  done | sort -u | grep -v -E '/(libc|libm|libstdc\+\+|libgcc_s|libpthread|libdl|librt)\.so|ld-linux'
}
for f in $(closure libOSMesa.so.8 libembree3.so.3 libbox2d.so.2 libyaml-cpp.so.0.7 libfmt.so.9 libgmp.so.10 \
                   libgmpxx.so.4 libmpfr.so.6 libjemalloc.so.2); do
  cp -L "$f" "$K/stage/kitlib/$(basename "$f")"
done
cp "$B"/libtoponav_{core,sim,mapping,planning,experiments}.a "$K/obj/"
cp "$B"/CMakeFiles/toponav.dir/experiments/main.cpp.o "$B"/CMakeFiles/toponav.dir/experiments/cli/*.o \
   "$B"/CMakeFiles/toponav.dir/experiments/internal/jemalloc_conf.c.o "$K/obj/"
strip --strip-debug "$K"/obj/*
# The OpenCV stand-in: every OpenCV symbol the prebuilt objects use, each a function that stops the program.
{
  echo '#include <stdio.h>'; echo '#include <stdlib.h>'
  echo 'static void Stop(const char* s) { fprintf(stderr, "toponav (gpu kit): %s needs OpenCV, not in this build\n", s); abort(); }'
  for f in "$K"/obj/*; do nm -u "$f" | awk '{print $2}'; done | sort -u | grep -E '^_Z(N|NK|TIN|TVN|TSN)2cv' |
    while read -r s; do
      case $s in _ZT*) echo "__attribute__((aligned(16))) char $s[256];" ;; *) echo "void $s(void) { Stop(\"$s\"); }" ;; esac
    done
} > "$K/opencv_stub.c"
gcc -shared -fPIC -O1 -Wl,-soname,libopencv_stub.so -o "$K/stage/kitlib/libopencv_stub.so" "$K/opencv_stub.c"
cp -r /usr/include/eigen3 /usr/include/nlohmann "$K/stage/kitinc/"
(cd "$K/stage" && tar cf - kitlib | xz -9e -T0 > ../libs.tar.xz && tar cf - kitinc | xz -9 -T0 > ../inc.tar.xz)
(cd "$K" && tar cf - obj | xz -9 -T0 > obj.tar.xz && rm -rf obj stage)
ls -la "$K"
