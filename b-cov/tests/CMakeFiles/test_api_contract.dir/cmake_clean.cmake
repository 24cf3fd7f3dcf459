file(REMOVE_RECURSE
  "CMakeFiles/test_api_contract.dir/api/test_api_contract.c.o"
  "CMakeFiles/test_api_contract.dir/api/test_api_contract.c.o.d"
  "test_api_contract"
  "test_api_contract.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C)
  include(CMakeFiles/test_api_contract.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
