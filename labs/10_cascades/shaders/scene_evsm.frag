#version 410 core
// PASS 2 of lab 10 with csm.filter=evsm: your lab 06 function (evsmVisibility) on each cascade's
// filtered map; cascades.glsl does the rest.
#define WB_EVSM
#include "../../06_evsm/shaders/exercise.glsl"
#include "cascades.glsl"
