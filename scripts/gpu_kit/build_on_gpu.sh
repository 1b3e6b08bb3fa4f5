#!/bin/bash
# On a machine with PyTorch and a C++ compiler but not our Debian packages: builds toponav from the repository
# and the kit scripts/gpu_kit/make_kit.sh made (.gpukit/), against that PyTorch's LibTorch (CUDA where it has
# it).  Run from the repository root; W (default /tmp/toponav_gpu) receives the program, W/toponav.
set -euo pipefail
REPO=$(pwd); KIT=$REPO/.gpukit; W=${W:-/tmp/toponav_gpu}
# LibTorch: PyTorch's own, or TORCH_INCLUDE and TORCH_LIB (e.g. /usr/include and /usr/lib/x86_64-linux-gnu).
if [ -z "${TORCH_LIB:-}" ]; then
  T=$(python3 -c "import torch, os; print(os.path.dirname(torch.__file__))")
  TORCH_INCLUDE=$T/include TORCH_LIB=$T/lib
  ABI=$(python3 -c "import torch; print(int(torch._C._GLIBCXX_USE_CXX11_ABI))")
fi
inc=(-isystem "$TORCH_INCLUDE/torch/csrc/api/include")
[ "$TORCH_INCLUDE" = /usr/include ] || inc+=(-isystem "$TORCH_INCLUDE")
mkdir -p "$W" && cd "$W"
for p in libs inc obj; do tar xJf "$KIT/$p.tar.xz"; done
srcs=("$REPO"/learning/*.cpp "$REPO"/learning/internal/*.cpp)
for f in "${srcs[@]}"; do  # the learning layer, the one that uses LibTorch
  g++ -O3 -DNDEBUG -fPIC -std=c++20 -D_GLIBCXX_USE_CXX11_ABI="${ABI:-1}" -I"$REPO" -isystem kitinc/eigen3 -isystem kitinc \
    "${inc[@]}" -c "$f" -o "learning_$(basename "$f").o" &
done
for job in $(jobs -p); do wait "$job" || { echo "build_on_gpu: a learning source failed to compile" >&2; exit 1; }; done
rm -f libtoponav_learning.a && ar rcs libtoponav_learning.a learning_*.o
torch=(-L"$TORCH_LIB" -Wl,--no-as-needed -ltorch -ltorch_cpu -lc10)
[ -f "$TORCH_LIB/libtorch_cuda.so" ] && torch+=(-ltorch_cuda -lc10_cuda)
# DT_RPATH (not RUNPATH): the kit's libraries find their own dependencies in kitlib too.
g++ -O3 obj/main.cpp.o obj/common.cpp.o obj/learning_commands.cpp.o obj/sensing_commands.cpp.o obj/jemalloc_conf.c.o \
  -o toponav obj/libtoponav_experiments.a libtoponav_learning.a obj/libtoponav_planning.a obj/libtoponav_mapping.a \
  obj/libtoponav_sim.a obj/libtoponav_core.a -Lkitlib -l:libfmt.so.9 -l:libyaml-cpp.so.0.7 -l:libembree3.so.3 \
  -l:libbox2d.so.2 -l:libOSMesa.so.8 -l:libgmpxx.so.4 -l:libmpfr.so.6 -l:libgmp.so.10 -l:libjemalloc.so.2 \
  -l:libopencv_stub.so "${torch[@]}" -Wl,--as-needed -Wl,--disable-new-dtags -Wl,-rpath,"$W/kitlib:$TORCH_LIB" -lpthread
"$W/toponav" info --cuda
