# --version shows the project's version.
cgcm_app_check(ARGS --version EXIT 0 STDOUT "^cgcm ${PROJECT_VERSION}")
