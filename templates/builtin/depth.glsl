#version 450
// hexc template `depth`: writes no colour and reads no slot, for depth-only passes. Materials that
// share it compile to one shader.
#include <hexc>

void main() {
}
