#!/usr/bin/env bash
# Counts the GLSL lines that have a C++ twin (docs/ARCHITECTURE.md, "What stays twin"): the files of the table's
# GLSL column that compute what a C++ function computes too, code lines only (no comments, blank lines,
# includes, braces alone). Issue 34 asks for fewer than 150.
set -euo pipefail
cd "$(dirname "$0")/../../Shaders"
twins=(Textures/ImageTexture.glsl Textures/Srgb.glsl Sphere.rchit Triangle.rchit Medium.rchit CameraSample.glsl
    Integrator.glsl SampleSum.glsl)
total=0
for f in "${twins[@]}"; do
    n=$(grep -cvE '^\s*(//|$|#include|#version|#extension|\{|\}|\};)' "$f")
    printf '%4d  Shaders/%s\n' "$n" "$f"
    total=$((total + n))
done
printf '%4d  GLSL code lines with a C++ twin\n' "$total"
