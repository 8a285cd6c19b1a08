#include <lacrima/FapAnimation.h>
