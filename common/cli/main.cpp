#include <lacrima/FapReader.h>
int main() { return 0; }
