#version 410 core
// PASS 2 of lab 10 with PCF: cascades.glsl does the work.
#include "cascades.glsl"
