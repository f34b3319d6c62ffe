#version 410 core
// PASS 2 of lab 10 with csm.filter=vsm: your lab 05 functions (chebyshevUpperBound,
// reduceLightBleeding) on each cascade's filtered moments; cascades.glsl does the rest.
#define WB_VSM
#include "../../05_vsm/shaders/exercise.glsl"
#include "cascades.glsl"
