# Empty dependencies file for test_hull_proof.
# This may be replaced when dependencies are built.
