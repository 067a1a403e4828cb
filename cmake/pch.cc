// The translation unit that compiles vivp's precompiled header (pch.cmake).
