#ifndef GOOD_INC
#define GOOD_INC
float twice(float x) { return 2.0 * x; }
#endif
