; An NSIS installer script: also a .nsi file, and no NSI scene.
!include "MUI2.nsh"
Name "Example"
OutFile "setup.exe"
Section
SectionEnd
