library(testthat)
library(trigspline)
test_check("trigspline")
