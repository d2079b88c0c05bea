// Placeholder so CMake configures while cli/ has no sources on this branch
// (interp2 builds only grammar/interpreter targets). Delete once real sources land.
