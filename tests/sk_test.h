/* Minimal test harness shared by every test program in tests/.
   Each test program includes this header (after shadowkit.h), defines its
   test functions, and ends with SK_TEST_MAIN(test_a, test_b, ...).
   Output: one line per failed check, then a summary line
       "<program>: N passed, M failed"
   which tests/run_tests.sh adds up. Exit status is non-zero on failure. */
#ifndef SK_TEST_H
#define SK_TEST_H
#include <math.h>
#include <stdio.h>
#include <string.h>

static int sk_test_passed_ = 0, sk_test_failed_ = 0;

#define SK_CHECK(cond) do { if (cond) sk_test_passed_++; else { sk_test_failed_++; \
    printf("FAIL %s:%d: %s\n", __FILE__, __LINE__, #cond); } } while (0)
#define SK_CHECK_MSG(cond, ...) do { if (cond) sk_test_passed_++; else { sk_test_failed_++; \
    printf("FAIL %s:%d: %s: ", __FILE__, __LINE__, #cond); printf(__VA_ARGS__); printf("\n"); } } while (0)
/* |a-b| <= tol, and neither is NaN */
#define SK_CHECK_NEAR(a, b, tol) do { double sk_a_ = (double)(a), sk_b_ = (double)(b); \
    if (sk_a_ == sk_a_ && sk_b_ == sk_b_ && fabs(sk_a_ - sk_b_) <= (double)(tol)) sk_test_passed_++; \
    else { sk_test_failed_++; printf("FAIL %s:%d: %s = %.9g, expected %s = %.9g (tol %g)\n", \
    __FILE__, __LINE__, #a, sk_a_, #b, sk_b_, (double)(tol)); } } while (0)
#define SK_CHECK_FINITE(x) SK_CHECK_MSG(isfinite((double)(x)), "%s = %g", #x, (double)(x))

typedef void (*sk_test_fn_)(void);
static int sk_test_run_(const char *prog, const sk_test_fn_ *fns, int n) {
    int i;
    for (i = 0; i < n; i++) fns[i]();
    printf("%s: %d passed, %d failed\n", prog, sk_test_passed_, sk_test_failed_);
    return sk_test_failed_ ? 1 : 0;
}
#define SK_TEST_MAIN(...) int main(int argc, char **argv) { \
    static const sk_test_fn_ fns_[] = { __VA_ARGS__ }; (void)argc; \
    return sk_test_run_(argv[0], fns_, (int)(sizeof fns_ / sizeof fns_[0])); }
#endif
