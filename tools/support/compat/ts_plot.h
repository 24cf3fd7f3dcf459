/* Transitional: the old ts_ names of tsu_plot.h for code not yet moved to the
 * tsu_ prefix (tests/test_review_fuzz.c).  Nothing under tools/ includes
 * this; delete it once no file includes "ts_plot.h". */
#ifndef TS_PLOT_H_COMPAT
#define TS_PLOT_H_COMPAT
#include "tsu_plot.h"

#define TS_ TSU_
#define TS_PLOT_BUF_INIT TSU_PLOT_BUF_INIT
#define TS_PLOT_DEFAULT_HEIGHT TSU_PLOT_DEFAULT_HEIGHT
#define TS_PLOT_DEFAULT_WIDTH TSU_PLOT_DEFAULT_WIDTH
#define TS_PLOT_ERR_ARG TSU_PLOT_ERR_ARG
#define TS_PLOT_ERR_IO TSU_PLOT_ERR_IO
#define TS_PLOT_ERR_NOMEM TSU_PLOT_ERR_NOMEM
#define TS_PLOT_ERR_NULL TSU_PLOT_ERR_NULL
#define TS_PLOT_ERR_OVERFLOW TSU_PLOT_ERR_OVERFLOW
#define TS_PLOT_FORBID_ABOVE TSU_PLOT_FORBID_ABOVE
#define TS_PLOT_FORBID_BELOW TSU_PLOT_FORBID_BELOW
#define TS_PLOT_LABEL_MAX TSU_PLOT_LABEL_MAX
#define TS_PLOT_LEGEND_AUTO TSU_PLOT_LEGEND_AUTO
#define TS_PLOT_LEGEND_LOWER_LEFT TSU_PLOT_LEGEND_LOWER_LEFT
#define TS_PLOT_LEGEND_LOWER_RIGHT TSU_PLOT_LEGEND_LOWER_RIGHT
#define TS_PLOT_LEGEND_NONE TSU_PLOT_LEGEND_NONE
#define TS_PLOT_LEGEND_OUTSIDE TSU_PLOT_LEGEND_OUTSIDE
#define TS_PLOT_LEGEND_UPPER_LEFT TSU_PLOT_LEGEND_UPPER_LEFT
#define TS_PLOT_LEGEND_UPPER_RIGHT TSU_PLOT_LEGEND_UPPER_RIGHT
#define TS_PLOT_MAX_ABS TSU_PLOT_MAX_ABS
#define TS_PLOT_MAX_SIZE TSU_PLOT_MAX_SIZE
#define TS_PLOT_MAX_TICKS TSU_PLOT_MAX_TICKS
#define TS_PLOT_MIN_SIZE TSU_PLOT_MIN_SIZE
#define TS_PLOT_OK TSU_PLOT_OK
#define TS_PLOT_RANGE_AUTO TSU_PLOT_RANGE_AUTO
#define TS_PLOT_RANGE_FIXED TSU_PLOT_RANGE_FIXED
#define ts_ tsu_
#define ts_plot tsu_plot
#define ts_plot_add_ceiling tsu_plot_add_ceiling
#define ts_plot_add_floor tsu_plot_add_floor
#define ts_plot_add_line tsu_plot_add_line
#define ts_plot_add_points tsu_plot_add_points
#define ts_plot_add_polygon tsu_plot_add_polygon
#define ts_plot_add_polyline tsu_plot_add_polyline
#define ts_plot_add_region tsu_plot_add_region
#define ts_plot_buf tsu_plot_buf
#define ts_plot_buf_append tsu_plot_buf_append
#define ts_plot_buf_free tsu_plot_buf_free
#define ts_plot_buf_init tsu_plot_buf_init
#define ts_plot_buf_printf tsu_plot_buf_printf
#define ts_plot_buf_puts tsu_plot_buf_puts
#define ts_plot_buf_xml tsu_plot_buf_xml
#define ts_plot_free tsu_plot_free
#define ts_plot_get_ticks tsu_plot_get_ticks
#define ts_plot_legend tsu_plot_legend
#define ts_plot_new tsu_plot_new
#define ts_plot_palette tsu_plot_palette
#define ts_plot_range_mode tsu_plot_range_mode
#define ts_plot_render tsu_plot_render
#define ts_plot_save tsu_plot_save
#define ts_plot_set_equal_aspect tsu_plot_set_equal_aspect
#define ts_plot_set_grid tsu_plot_set_grid
#define ts_plot_set_labels tsu_plot_set_labels
#define ts_plot_set_legend tsu_plot_set_legend
#define ts_plot_set_simplify tsu_plot_set_simplify
#define ts_plot_set_title tsu_plot_set_title
#define ts_plot_set_xml_declaration tsu_plot_set_xml_declaration
#define ts_plot_set_xrange tsu_plot_set_xrange
#define ts_plot_set_yrange tsu_plot_set_yrange
#define ts_plot_side tsu_plot_side
#define ts_plot_status tsu_plot_status
#define ts_plot_strerror tsu_plot_strerror
#define ts_plot_style tsu_plot_style
#define ts_plot_test_fail_alloc_after tsu_plot_test_fail_alloc_after
#define ts_plot_ticks tsu_plot_ticks
#define ts_plot_ticks_compute tsu_plot_ticks_compute
#define ts_plot_write tsu_plot_write

#endif
