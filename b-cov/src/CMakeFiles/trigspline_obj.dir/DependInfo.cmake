
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/wt/trust/src/accuracy.c" "src/CMakeFiles/trigspline_obj.dir/accuracy.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/accuracy.c.o.d"
  "/work/wt/trust/src/basis.c" "src/CMakeFiles/trigspline_obj.dir/basis.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/basis.c.o.d"
  "/work/wt/trust/src/certificate.c" "src/CMakeFiles/trigspline_obj.dir/certificate.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/certificate.c.o.d"
  "/work/wt/trust/src/checks.c" "src/CMakeFiles/trigspline_obj.dir/checks.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/checks.c.o.d"
  "/work/wt/trust/src/controls.c" "src/CMakeFiles/trigspline_obj.dir/controls.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/controls.c.o.d"
  "/work/wt/trust/src/curve.c" "src/CMakeFiles/trigspline_obj.dir/curve.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/curve.c.o.d"
  "/work/wt/trust/src/deprecated.c" "src/CMakeFiles/trigspline_obj.dir/deprecated.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/deprecated.c.o.d"
  "/work/wt/trust/src/deriv.c" "src/CMakeFiles/trigspline_obj.dir/deriv.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/deriv.c.o.d"
  "/work/wt/trust/src/errmsg.c" "src/CMakeFiles/trigspline_obj.dir/errmsg.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/errmsg.c.o.d"
  "/work/wt/trust/src/eval.c" "src/CMakeFiles/trigspline_obj.dir/eval.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/eval.c.o.d"
  "/work/wt/trust/src/find.c" "src/CMakeFiles/trigspline_obj.dir/find.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/find.c.o.d"
  "/work/wt/trust/src/geometric.c" "src/CMakeFiles/trigspline_obj.dir/geometric.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/geometric.c.o.d"
  "/work/wt/trust/src/interval.c" "src/CMakeFiles/trigspline_obj.dir/interval.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/interval.c.o.d"
  "/work/wt/trust/src/kernels.c" "src/CMakeFiles/trigspline_obj.dir/kernels.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/kernels.c.o.d"
  "/work/wt/trust/src/numfmt.c" "src/CMakeFiles/trigspline_obj.dir/numfmt.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/numfmt.c.o.d"
  "/work/wt/trust/src/repair.c" "src/CMakeFiles/trigspline_obj.dir/repair.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/repair.c.o.d"
  "/work/wt/trust/src/report.c" "src/CMakeFiles/trigspline_obj.dir/report.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/report.c.o.d"
  "/work/wt/trust/src/shape.c" "src/CMakeFiles/trigspline_obj.dir/shape.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/shape.c.o.d"
  "/work/wt/trust/src/slopes.c" "src/CMakeFiles/trigspline_obj.dir/slopes.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/slopes.c.o.d"
  "/work/wt/trust/src/solve.c" "src/CMakeFiles/trigspline_obj.dir/solve.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/solve.c.o.d"
  "/work/wt/trust/src/spline.c" "src/CMakeFiles/trigspline_obj.dir/spline.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/spline.c.o.d"
  "/work/wt/trust/src/status.c" "src/CMakeFiles/trigspline_obj.dir/status.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/status.c.o.d"
  "/work/wt/trust/src/surface.c" "src/CMakeFiles/trigspline_obj.dir/surface.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/surface.c.o.d"
  "/work/wt/trust/src/surface_cert.c" "src/CMakeFiles/trigspline_obj.dir/surface_cert.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/surface_cert.c.o.d"
  "/work/wt/trust/src/surface_eval.c" "src/CMakeFiles/trigspline_obj.dir/surface_eval.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/surface_eval.c.o.d"
  "/work/wt/trust/src/surface_net.c" "src/CMakeFiles/trigspline_obj.dir/surface_net.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/surface_net.c.o.d"
  "/work/wt/trust/src/trigmin.c" "src/CMakeFiles/trigspline_obj.dir/trigmin.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/trigmin.c.o.d"
  "/work/wt/trust/src/vocab.c" "src/CMakeFiles/trigspline_obj.dir/vocab.c.o" "gcc" "src/CMakeFiles/trigspline_obj.dir/vocab.c.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "")
