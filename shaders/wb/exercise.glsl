// Shared by every lab's exercise file. A stub returns WB_TODO (or a vector of it) so the app and the
// test harness can tell "not implemented yet" from a wrong answer.
#ifndef WB_EXERCISE_GLSL
#define WB_EXERCISE_GLSL
const float WB_TODO = -7.0e30;
bool wbIsTodo(float v) { return v <= -1.0e29; }
bool wbIsTodo(vec3 v) { return v.x <= -1.0e29 || v.y <= -1.0e29 || v.z <= -1.0e29; }
#endif
