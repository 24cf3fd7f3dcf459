# Empty dependencies file for test_api_contract.
# This may be replaced when dependencies are built.
