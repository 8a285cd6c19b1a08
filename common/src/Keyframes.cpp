#include <lacrima/Keyframes.h>
