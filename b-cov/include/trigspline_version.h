/* trigspline_version.h: the library's version, generated from
 * project(trigspline VERSION ...) in CMakeLists.txt (the one place the
 * version is written) by configure_file, or by the Python package's build
 * from the same template.  Do not edit; included by trigspline.h. */
#ifndef TRIGSPLINE_VERSION_H
#define TRIGSPLINE_VERSION_H

#define TS_VERSION_MAJOR 0
#define TS_VERSION_MINOR 2
#define TS_VERSION_PATCH 0
/* "MAJOR.MINOR.PATCH" */
#define TS_VERSION_STRING "0.2.0"
/* One integer that grows with the version: MAJOR << 16 | MINOR << 8 | PATCH
 * (each part below 256), e.g. 0x000200 for 0.2.0; compare with < and >=. */
#define TS_VERSION_NUM ((TS_VERSION_MAJOR << 16) | (TS_VERSION_MINOR << 8) | TS_VERSION_PATCH)
/* Nonzero when the header is version maj.min.pat or later:
 *   #if TS_VERSION_AT_LEAST(0, 2, 0) ... #endif */
#define TS_VERSION_AT_LEAST(maj, min, pat) \
    (TS_VERSION_NUM >= (((maj) << 16) | ((min) << 8) | (pat)))

#endif /* TRIGSPLINE_VERSION_H */
