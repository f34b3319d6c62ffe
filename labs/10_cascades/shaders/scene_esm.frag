#version 410 core
// PASS 2 of lab 10 with csm.filter=esm: your lab 04 function (esmVisibility) on each cascade's
// filtered map; cascades.glsl does the rest.
#define WB_ESM
#include "../../04_esm/shaders/exercise.glsl"
#include "cascades.glsl"
