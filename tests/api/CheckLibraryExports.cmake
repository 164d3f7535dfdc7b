# Checks libanari's SONAME and that it exports exactly the C functions and
# backend C++ symbols of docs/ABI.md. Run as: cmake -DLIBRARY=... -P this.
execute_process(COMMAND readelf -d ${LIBRARY} OUTPUT_VARIABLE dynamic)
if(NOT dynamic MATCHES "Library soname: \\[libanari\\.so\\.0\\]")
  message(FATAL_ERROR "SONAME is not libanari.so.0:\n${dynamic}")
endif()

execute_process(COMMAND nm -D --defined-only ${LIBRARY} OUTPUT_VARIABLE raw)
execute_process(COMMAND nm -DC --defined-only ${LIBRARY} OUTPUT_VARIABLE demangled)

set(c_functions
  anariLoadLibrary anariUnloadLibrary anariLoadModule anariUnloadModule
  anariNewDevice anariNewInitializedDevice anariNewArray1D anariNewArray2D
  anariNewArray3D anariMapArray anariUnmapArray anariNewLight anariNewCamera
  anariNewGeometry anariNewSpatialField anariNewVolume anariNewSurface
  anariNewMaterial anariNewSampler anariNewGroup anariNewInstance anariNewWorld
  anariNewObject anariSetParameter anariUnsetParameter anariUnsetAllParameters
  anariMapParameterArray1D anariMapParameterArray2D anariMapParameterArray3D
  anariUnmapParameterArray anariCommitParameters anariRelease anariRetain
  anariGetDeviceSubtypes anariGetDeviceExtensions anariGetObjectSubtypes
  anariGetObjectInfo anariGetParameterInfo anariGetProperty anariNewFrame
  anariMapFrame anariUnmapFrame anariNewRenderer anariRenderFrame
  anariFrameReady anariDiscardFrame anariDeviceGetProcAddress _anari_anchor)
list(LENGTH c_functions count)
if(NOT count EQUAL 48)
  message(FATAL_ERROR "expected 46 API functions + 2 extras, listed ${count}")
endif()
foreach(f ${c_functions})
  if(NOT raw MATCHES " T ${f}\n")
    message(FATAL_ERROR "libanari does not export ${f}")
  endif()
endforeach()

# Backend symbols, matched on the mangled names the SDK's binaries use, so
# the parameter types (ANARIDataType as a class, tag-struct handles) match.
set(mangled
  "_ZN5anari11LibraryImplC1EPvPFvPKvPNS_3api6DeviceEPNS4_6ObjectE13ANARIDataTypeiiPKcES3_"
  "_ZN5anari11LibraryImplC2EPvPFvPKvPNS_3api6DeviceEPNS4_6ObjectE13ANARIDataTypeiiPKcES3_"
  "_ZN5anari11LibraryImplD0Ev" "_ZN5anari11LibraryImplD1Ev"
  "_ZNK5anari11LibraryImpl15defaultStatusCBEv"
  "_ZNK5anari11LibraryImpl22defaultStatusCBUserPtrEv"
  "_ZNK5anari11LibraryImpl12this_libraryEv"
  "_ZNK5anari11LibraryImpl13libraryHandleEv"
  "_ZN5anari16loadANARILibraryERKNSt7__cxx1112basic_stringIcSt11char_traitsIcESaIcEEE"
  "_ZN5anari11freeLibraryEPv"
  "_ZN5anari16getSymbolAddressEPvRKNSt7__cxx1112basic_stringIcSt11char_traitsIcESaIcEEE"
  "_ZTVN5anari11LibraryImplE" "_ZTIN5anari11LibraryImplE"
  "_ZTVN5anari10DeviceImplE" "_ZTIN5anari10DeviceImplE")
foreach(symbol ${mangled})
  if(NOT raw MATCHES "${symbol}\n")
    message(FATAL_ERROR "libanari does not export ${symbol}")
  endif()
endforeach()

# Nothing else of ours leaks: every other export is a C++ runtime detail.
string(REGEX MATCHALL "prism::[^\n]*" leaked "${demangled}")
if(leaked)
  message(FATAL_ERROR "internal symbols exported: ${leaked}")
endif()
message(STATUS "libanari: SONAME and ${count} C functions and backend symbols OK")
