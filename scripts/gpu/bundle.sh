#!/usr/bin/env bash
# Packs executables for a headless GPU server that has no package registry: the executables,
# the shared libraries they load that such a server lacks (spdlog, fmt, glfw, tinygltf, embree,
# ...; not glibc, libstdc++ or the GL/EGL dispatch libraries), and the GLVND/EGL Debian packages,
# which env.sh unpacks there. Shaders and technique graphs are embedded in the binaries.
#   scripts/gpu/bundle.sh OUTDIR EXECUTABLE...
# On the server, from a copy of the checkout that carries OUTDIR:
#   source OUTDIR/env.sh && OUTDIR/bin/penumbra info --context egl
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 OUTDIR EXECUTABLE..." >&2; exit 2; }
out=$1
shift
mkdir -p "$out/bin" "$out/lib" "$out/debs"
# The server provides these itself, or gets them from the GLVND packages below.
provided='^(linux-vdso|ld-linux|libc|libm|libdl|libpthread|librt|libgcc_s|libstdc\+\+|libEGL|libGL|libGLX|libOpenGL|libGLdispatch|libGLESv2)\.'
for exe in "$@"; do
  [ -x "$exe" ] || { echo "not an executable: $exe" >&2; exit 2; }
  cp -L "$exe" "$out/bin/"
  while read -r lib path; do
    [[ $lib =~ $provided ]] || cp -Ln "$path" "$out/lib/" 2>/dev/null || true
  done < <(ldd "$exe" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}')
done
if ! compgen -G "$out/debs/libegl1_*.deb" >/dev/null; then
  (cd "$out/debs" && apt-get download libglvnd0 libegl1 libopengl0 libgl1 libglx0 libgles2 >/dev/null 2>&1) ||
    echo "warning: could not download the GLVND packages (no apt?); the server must have libEGL" >&2
fi
cat > "$out/env.sh" <<'ENV'
# Sourced on the GPU server: unpacks GLVND/EGL, points GLVND at NVIDIA's EGL vendor file and the
# loader at the bundled libraries.
bundle_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
for deb in "$bundle_dir"/debs/*.deb; do dpkg -x "$deb" /; done
ldconfig
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
export LD_LIBRARY_PATH="$bundle_dir/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
ENV
echo "bundle $out: $(du -sh "$out" | cut -f1) (a device run carries at most 64 MiB)"
