/* test_isa_<variant>: tests/api/test_core.c (renamed test_core_main;
 * test_isa_histo_<variant>: tests/api/test_histo.c, TS_ISA_MAIN) linked
 * against a library whose TS_VECTOR_LOOP functions are compiled for one
 * instruction set only (tests/isa/CMakeLists.txt), so that every clone the
 * shipped build dispatches at run time is tested on any CPU that can run it,
 * not only the one ifunc picks here.  Skipped (0 passed, 0 failed) where
 * the CPU lacks the instruction set. */
#include <stdio.h>

#if !defined(TS_ISA_MAIN)
#define TS_ISA_MAIN test_core_main
#endif

int TS_ISA_MAIN(void);

int main(void)
{
#if defined(TS_ISA_NEEDS)
    __builtin_cpu_init();
    if (!__builtin_cpu_supports(TS_ISA_NEEDS)) {
        printf("%s: skipped, the CPU lacks %s\n", TS_ISA_NAME, TS_ISA_NEEDS);
        printf("%s: 0 passed, 0 failed\n", TS_ISA_NAME);
        return 0;
    }
#endif
    return TS_ISA_MAIN();
}
