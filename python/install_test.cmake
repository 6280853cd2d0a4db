# Installs the Python package (component python) into a scratch prefix and imports it from there with the
# binding's interpreter. Called by CTest with -DBUILD_DIR -DWORK_DIR -DPYTHON -DPACKAGE_DIR -DDATA.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix" --component python
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install --component python failed")
endif()
# Run from the scratch folder, so that nothing but the installed package can be imported as dlfl.
set(script "import dlfl, os, sys
assert os.path.realpath(dlfl.__file__).startswith(os.path.realpath(sys.argv[1]) + os.sep), dlfl.__file__
m = dlfl.read_mesh(sys.argv[2])
assert (m.num_vertices, m.num_edges, m.num_faces) == (8, 12, 6)
assert os.path.exists(os.path.join(os.path.dirname(dlfl.__file__), '__init__.pyi'))
print('installed dlfl', dlfl.__version__, 'at', os.path.dirname(dlfl.__file__))")
execute_process(COMMAND "${CMAKE_COMMAND}" -E env "PYTHONPATH=${WORK_DIR}/prefix/${PACKAGE_DIR}" PYTHONNOUSERSITE=1
                        PYTHONDONTWRITEBYTECODE=1 "${PYTHON}" -c "${script}" "${WORK_DIR}/prefix" "${DATA}/cube.obj"
                WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed package does not import or work")
endif()
