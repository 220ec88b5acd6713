# Method 1 on the quarter model through image cells (../../regression/method1_quarter_model):
# each rank evaluates the pairs of the cells it owns, the images' columns included; np = 1
# and np = 2 give the same curve (1e-7) and the same results.e.
cgcm_ranks_agree()
