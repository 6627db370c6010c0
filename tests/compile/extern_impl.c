/* The one translation unit that holds the (extern) implementation. */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
