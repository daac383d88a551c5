// Run-time options every fuzz target is linked with, so a target and a reproduction of one of its
// crash files behave the same without any environment: undefined behaviour stops the run (libFuzzer
// then records the input), except what ubsan_suppressions.txt lists.
extern "C" const char* __ubsan_default_options() {
  return "halt_on_error=1:print_stacktrace=1:suppressions=" BRDFKIT_FUZZ_UBSAN_SUPPRESSIONS;
}
