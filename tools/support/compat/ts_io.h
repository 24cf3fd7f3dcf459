/* Transitional: the old ts_ names of tsu_io.h for code not yet moved to the
 * tsu_ prefix (tests/test_review_fuzz.c).  Nothing under tools/ includes
 * this; delete it once no file includes "ts_io.h". */
#ifndef TS_IO_H_COMPAT
#define TS_IO_H_COMPAT
#include "tsu_io.h"

#define TS_ TSU_
#define TS_DELIM_AUTO TSU_DELIM_AUTO
#define TS_DELIM_COMMA TSU_DELIM_COMMA
#define TS_DELIM_SPACE TSU_DELIM_SPACE
#define TS_DELIM_TAB TSU_DELIM_TAB
#define TS_FMT_SIZE TSU_FMT_SIZE
#define TS_HEADER_AUTO TSU_HEADER_AUTO
#define TS_HEADER_NONE TSU_HEADER_NONE
#define TS_HEADER_YES TSU_HEADER_YES
#define TS_IO_BUFFER TSU_IO_BUFFER
#define TS_IO_END TSU_IO_END
#define TS_IO_ERR_EMPTY TSU_IO_ERR_EMPTY
#define TS_IO_ERR_FIELDS TSU_IO_ERR_FIELDS
#define TS_IO_ERR_LINE TSU_IO_ERR_LINE
#define TS_IO_ERR_NOMEM TSU_IO_ERR_NOMEM
#define TS_IO_ERR_NONFINITE TSU_IO_ERR_NONFINITE
#define TS_IO_ERR_NULL TSU_IO_ERR_NULL
#define TS_IO_ERR_NUMBER TSU_IO_ERR_NUMBER
#define TS_IO_ERR_OPEN TSU_IO_ERR_OPEN
#define TS_IO_ERR_OPTION TSU_IO_ERR_OPTION
#define TS_IO_ERR_OVERFLOW TSU_IO_ERR_OVERFLOW
#define TS_IO_ERR_RANGE TSU_IO_ERR_RANGE
#define TS_IO_ERR_READ TSU_IO_ERR_READ
#define TS_IO_MAX_LINE TSU_IO_MAX_LINE
#define TS_IO_MSG_SIZE TSU_IO_MSG_SIZE
#define TS_IO_OK TSU_IO_OK
#define TS_IO_STATUS_COUNT_ TSU_IO_STATUS_COUNT_
#define TS_NUM_NONFINITE TSU_NUM_NONFINITE
#define TS_NUM_OK TSU_NUM_OK
#define TS_NUM_RANGE TSU_NUM_RANGE
#define TS_NUM_SYNTAX TSU_NUM_SYNTAX
#define TS_OUT_FSYNC TSU_OUT_FSYNC
#define ts_ tsu_
#define ts_delim tsu_delim
#define ts_format_double tsu_format_double
#define ts_header tsu_header
#define ts_io__fail_alloc_after tsu_io__fail_alloc_after
#define ts_io__pow10_entry tsu_io__pow10_entry
#define ts_io_error tsu_io_error
#define ts_io_status tsu_io_status
#define ts_io_strerror tsu_io_strerror
#define ts_num_status tsu_num_status
#define ts_out tsu_out
#define ts_out_abort tsu_out_abort
#define ts_out_commit tsu_out_commit
#define ts_out_file tsu_out_file
#define ts_out_open tsu_out_open
#define ts_out_path tsu_out_path
#define ts_out_temp tsu_out_temp
#define ts_parse_double tsu_parse_double
#define ts_read_options tsu_read_options
#define ts_read_options_init tsu_read_options_init
#define ts_read_table tsu_read_table
#define ts_read_table_path tsu_read_table_path
#define ts_reader tsu_reader
#define ts_reader_delim tsu_reader_delim
#define ts_reader_free tsu_reader_free
#define ts_reader_line tsu_reader_line
#define ts_reader_name tsu_reader_name
#define ts_reader_ncols tsu_reader_ncols
#define ts_reader_next tsu_reader_next
#define ts_reader_nnames tsu_reader_nnames
#define ts_reader_open tsu_reader_open
#define ts_reader_rows tsu_reader_rows
#define ts_reader_source tsu_reader_source
#define ts_table tsu_table
#define ts_table_free tsu_table_free
#define ts_writer tsu_writer
#define ts_writer_flush tsu_writer_flush
#define ts_writer_free tsu_writer_free
#define ts_writer_new tsu_writer_new
#define ts_writer_row tsu_writer_row
#define ts_writer_text tsu_writer_text
#define ts_writer_xy tsu_writer_xy

#endif
