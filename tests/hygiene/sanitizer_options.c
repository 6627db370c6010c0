/* sanitizer_options.c - linked into every program of the `hygiene` flavour
   (mk/hygiene.mk): the sanitizer runtimes read these defaults at start-up,
   so a program run by hand behaves as under tests/run_tests.sh.
   detect_leaks: LeakSanitizer at exit (the point of the flavour);
   abort_on_error / halt_on_error: the first report ends the program with a
   non-zero status, which run_tests.sh counts as a failure after the
   summary line; verify_asan_link_order=0: run_tests.sh preloads libstdbuf
   (line-buffered output), which would otherwise stop ASan at start-up.
   Environment variables (ASAN_OPTIONS, ...) still override these. */
const char *__asan_default_options(void);
const char *__ubsan_default_options(void);

const char *__asan_default_options(void)
{
    return "detect_leaks=1:abort_on_error=1:verify_asan_link_order=0:strict_string_checks=1:"
           "detect_stack_use_after_return=1:check_initialization_order=1";
}

const char *__ubsan_default_options(void)
{
    return "print_stacktrace=1:halt_on_error=1";
}
