// One test per kind of error in a scene text: each checks the reported line:column (the
// culprit token) and that the message says what is wrong and what is allowed.

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "scene/scene_file.h"

namespace prt {
namespace {

// Two lines, so that the text under test starts on line 3.
const std::string kErrorPreamble = "camera { eye 0 0 -5 look_at 0 0 0 }\nimage { width 4 height 3 }\n";

InputError errorOf(const std::string& text) {
  try {
    parseScene(text, "bad.scene");
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError("(no error)");
}

void expectError(const std::string& text, int line, int column,
                 std::initializer_list<std::string> fragments) {
  const InputError error = errorOf(text);
  const std::string message = error.what();
  EXPECT_EQ(error.where().file, "bad.scene") << message;
  EXPECT_EQ(error.where().line, line) << message;
  EXPECT_EQ(error.where().column, column) << message;
  for (const std::string& fragment : fragments) {
    EXPECT_NE(message.find(fragment), std::string::npos)
        << "message: " << message << "\nlacks: " << fragment;
  }
}

// `body` goes on line 3, after a valid camera and image.
void expectBodyError(const std::string& body, int column,
                     std::initializer_list<std::string> fragments) {
  expectError(kErrorPreamble + body, 3, column, fragments);
}

TEST(SceneErrors, UnknownDirectiveListsTheValidOnes) {
  expectBodyError("spher { center 0 0 0 radius 1 }", 1,
                  {"unknown directive 'spher' (did you mean 'sphere'?)",
                   "camera, image, environment, sampling, material, light, sphere, box, plane"});
}

TEST(SceneErrors, NonWordWhereADirectiveBelongs) {
  expectBodyError("sphere { center 0 0 0 radius 1 } 7", 34, {"expected a directive", "'7'"});
  expectBodyError("}", 1, {"unexpected '}'"});
}

TEST(SceneErrors, UnknownParameterListsTheBlocksParameters) {
  expectBodyError("sphere { center 0 0 0 radus 1 }", 23,
                  {"unknown parameter 'radus' in the 'sphere' block (did you mean 'radius'?); "
                   "valid parameters: center, radius, surface"});
  expectBodyError("sphere { center 0 0 0 radius 1 surface { colour 1 0 0 } }", 42,
                  {"unknown parameter 'colour'",
                   "color, ambient, diffuse, specular, phong, "
                   "reflect, transmit, ior, gloss, translucency"});
  expectBodyError("light point { position 0 0 0 radius 1 }", 30,
                  {"unknown parameter 'radius' in the 'light point' block; valid parameters: "
                   "position, color"});
}

TEST(SceneErrors, MissingClosingBraceIsHinted) {
  expectError(kErrorPreamble + "sphere { center 0 0 0 radius 1\nbox { min 0 0 0 max 1 1 1 }", 4, 1,
              {"unknown parameter 'box'", "'}' of the block opened at line 3, column 8"});
}

TEST(SceneErrors, TooManyNumbersIsHinted) {
  expectBodyError("sphere { center 0 0 0 1 radius 1 }", 23,
                  {"expected a parameter name or '}'", "found '1'", "too many numbers"});
}

TEST(SceneErrors, DuplicateParameter) {
  expectBodyError("sphere { radius 1 center 0 0 0 radius 2 }", 32,
                  {"duplicate parameter 'radius'", "already given at line 3, column 10"});
}

TEST(SceneErrors, DuplicateSceneWideBlocks) {
  expectError(kErrorPreamble + "camera { eye 0 0 1 look_at 0 0 0 }", 3, 1,
              {"duplicate 'camera' block", "line 1, column 1"});
  expectError(kErrorPreamble + "image { width 4 height 3 }", 3, 1,
              {"duplicate 'image' block", "line 2, column 1"});
  expectError(kErrorPreamble + "environment { }\nenvironment { }", 4, 1,
              {"duplicate 'environment' block", "line 3, column 1"});
  expectError(kErrorPreamble + "sampling { }\n  sampling { }", 4, 3, {"duplicate 'sampling' block"});
}

TEST(SceneErrors, MalformedMaterialName) {
  expectBodyError("material frosted-glass { gloss 5 }", 10,
                  {"malformed material name 'frosted-glass'", "letters, digits and '_'"});
}

TEST(SceneErrors, DuplicateMaterialName) {
  expectError(kErrorPreamble + "material red { color 1 0 0 }\nmaterial red { color 1 0 0 }", 4, 10,
              {"material 'red' is already defined at line 3, column 10"});
}

TEST(SceneErrors, UnknownMaterialListsTheDefinedOnes) {
  expectBodyError(
      "material red { } material blue { }  sphere { center 0 0 0 radius 1 surface "
      "green }",
      76, {"unknown material 'green'", "defined materials: blue, red"});
  expectBodyError("material red { } sphere { center 0 0 0 radius 1 surface Red }", 57,
                  {"unknown material 'Red' (did you mean 'red'?)"});
  expectBodyError("sphere { center 0 0 0 radius 1 surface glass }", 40,
                  {"unknown material 'glass'", "no materials are defined"});
}

TEST(SceneErrors, SurfaceNeedsANameOrABlock) {
  expectBodyError("sphere { center 0 0 0 radius 1 surface 3 }", 40,
                  {"expected a material name or a '{ ... }' block", "'3'"});
  expectBodyError("material { color 1 1 1 }", 10, {"expected a material name", "'{'"});
}

TEST(SceneErrors, MalformedNumbers) {
  expectBodyError("sphere { center 0 1.2.3 0 radius 1 }", 19,
                  {"malformed number '1.2.3'", "'center' (y)"});
  expectBodyError("sphere { center 0,0,0 radius 1 }", 17, {"not commas"});
  expectBodyError("sphere { center 0 0 0 radius 1x }", 30, {"malformed number '1x'", "'radius'"});
}

TEST(SceneErrors, NonFiniteNumbers) {
  expectBodyError("sphere { center 0 0 0 radius nan }", 30, {"'radius' must be a finite number"});
  expectBodyError("sphere { center 0 Inf 0 radius 1 }", 19, {"finite number", "'Inf'"});
  expectBodyError("sphere { center 0 0 -inf radius 1 }", 21, {"finite number", "'-inf'"});
}

TEST(SceneErrors, NumbersBeyondDoublePrecision) {
  expectBodyError("sphere { center 0 0 0 radius 1e999 }", 30, {"'1e999'", "beyond double"});
}

TEST(SceneErrors, WrongKindOfValue) {
  expectBodyError("sphere { center 0 0 radius 1 }", 21,
                  {"'center' needs 3 numbers (x y z)", "found 'radius' after 2"});
  expectBodyError("sphere { center 0 0 0 radius }", 30, {"'radius' needs a number", "'}'"});
  expectBodyError("light point { position 0 0 0 color 1 1 }", 40,
                  {"'color' needs 3 numbers (r g b)"});
  expectError("camera { eye 0 0 -5 look_at 0 0 0 }\nimage { width 4 height 3 output fig.png }", 2,
              33, {"'output' needs a quoted string"});
}

TEST(SceneErrors, ColoursOutsideTheirRange) {
  expectBodyError("light point { position 0 0 0 color 1 -0.5 1 }", 38,
                  {"'color' (g) must be in [0, 1e+06], found -0.5"});
  expectBodyError("environment { background 0 0 -1 }", 30,
                  {"'background' (b) must be in [0, 1e+06]"});
  // Huge values would make pixels infinite.
  expectBodyError("light point { position 0 0 0 color 1e300 1 1 }", 36,
                  {"'color' (r) must be in [0, 1e+06], found 1e+300"});
  expectBodyError("environment { ambient 1 1000001 1 }", 25, {"'ambient' (g) must be in [0, 1e+06]"});
  expectBodyError("sphere { center 0 0 0 radius 1 surface { color 2e6 0 0 } }", 48,
                  {"'color' (r) must be in [0, 1e+06]"});
  expectBodyError("light rect { corner 0 0 0 edge1 1 0 0 edge2 0 1 0 color 0 0 1e7 }", 61,
                  {"'color' (b)"});
}

TEST(SceneErrors, SurfacesThatSendOnMoreLightThanReachesThem) {
  const std::string sphere = "sphere { center 0 0 0 radius 1 surface { ";
  const int column = static_cast<int>(sphere.size()) + 1;
  // Reported at the later of the two.
  expectBodyError(sphere + "reflect 1 transmit 1 } }", column + 19,
                  {"'reflect' + 'transmit' must be at most 1", "found 1 + 1"});
  expectBodyError(sphere + "transmit 0.6 reflect 0.5 } }", column + 21,
                  {"'reflect' + 'transmit' must be at most 1", "found 0.5 + 0.6"});
  // Inherited from a material: reported where this block adds the excess.
  const std::string glassSphere = "sphere { center 0 0 0 radius 1 surface glass { reflect 0.2 } }";
  expectError(kErrorPreamble + "material glass { transmit 0.9 }\n" + glassSphere, 4,
              static_cast<int>(glassSphere.find("0.2")) + 1, {"found 0.2 + 0.9"});
}

TEST(SceneErrors, SurfaceValueRanges) {
  const std::string sphere = "sphere { center 0 0 0 radius 1 surface { ";
  const int column = static_cast<int>(sphere.size()) + 1;
  expectBodyError(sphere + "diffuse 1.5 } }", column + 8,
                  {"'diffuse' must be in [0, 1], found 1.5"});
  expectBodyError(sphere + "ambient -0.1 } }", column + 8, {"'ambient' must be in [0, 1]"});
  expectBodyError(sphere + "specular 2 } }", column + 9, {"'specular' must be in [0, 1]"});
  expectBodyError(sphere + "reflect 1.01 } }", column + 8, {"'reflect' must be in [0, 1]"});
  expectBodyError(sphere + "transmit -1 } }", column + 9, {"'transmit' must be in [0, 1]"});
  expectBodyError(sphere + "phong 0.5 } }", column + 6, {"'phong' must be >= 1, found 0.5"});
  expectBodyError(sphere + "ior 0.9 } }", column + 4, {"'ior' must be in [1, 10], found 0.9"});
  expectBodyError(sphere + "ior 11 } }", column + 4, {"'ior' must be in [1, 10]"});
  expectBodyError(sphere + "gloss 90 } }", column + 6, {"'gloss' must be in [0, 90), found 90"});
  expectBodyError(sphere + "translucency -1 } }", column + 13,
                  {"'translucency' must be in [0, 90)"});
}

TEST(SceneErrors, SizeRanges) {
  expectBodyError("sphere { center 0 0 0 radius 0 }", 30, {"'radius' must be in (0, 1e+09]"});
  expectBodyError("light sphere { center 0 0 0 radius -1 }", 36, {"'radius' must be in (0, "});
  expectBodyError("sphere { center 0 0 2e9 radius 1 }", 21,
                  {"'center' (z) must be in [-1e+09, 1e+09]"});
}

TEST(SceneErrors, BoxMinMustBeBelowMax) {
  expectBodyError("box { min 0 1 0 max 1 1 1 }", 23,
                  {"'max' must exceed its 'min' on every axis", "on y max is 1 and min is 1"});
}

TEST(SceneErrors, CameraRanges) {
  expectError("camera { eye 0 0 -5 look_at 0 0 0 fov 180 }\nimage { width 4 height 3 }", 1, 39,
              {"'fov' must be in (0, 180), found 180"});
  expectError("camera { eye 0 0 -5 look_at 0 0 -5 }\nimage { width 4 height 3 }", 1, 29,
              {"'look_at' equals its 'eye'"});
  expectError("camera { eye 0 0 -5 look_at 0 0 0 up 0 0 2 }\nimage { width 4 height 3 }", 1, 38,
              {"'up' is parallel to its view direction"});
  expectError("camera { eye 0 0 -5 look_at 0 0 0 up 0 0 0 }\nimage { width 4 height 3 }", 1, 38,
              {"'up' must not be zero"});
  expectError("camera { eye 0 0 0 look_at 0 0 1e-300 }\nimage { width 4 height 3 }", 1, 28,
              {"'look_at' equals its 'eye'"});
  expectError("camera { eye 0 5 0 look_at 0 0 0 }\nimage { width 4 height 3 }", 1, 1,
              {"default 'up' (0 1 0) is parallel", "give an 'up'"});
}

TEST(SceneErrors, IntegerParameters) {
  expectError(kErrorPreamble + "environment { max_depth 65 }", 3, 25,
              {"'max_depth' must be a whole number in [0, 64], found '65'"});
  expectError(kErrorPreamble + "sampling { samples 0 }", 3, 20,
              {"'samples' must be a whole number in [1, 4096], found '0'"});
  expectError(kErrorPreamble + "sampling { samples 4097 }", 3, 20, {"[1, 4096]"});
  expectError(kErrorPreamble + "sampling { drt 65 }", 3, 16,
              {"'drt' must be a whole number in [1, 64]"});
}

TEST(SceneErrors, ImageSizes) {
  const std::string camera = "camera { eye 0 0 -5 look_at 0 0 0 }\n";
  expectError(camera + "image { width 3.5 height 3 }", 2, 15,
              {"'width' must be a whole number in [1, 32768], found '3.5'"});
  expectError(camera + "image { width 4 height 40000 }", 2, 24, {"'height'", "[1, 32768]"});
  expectError(camera + "image { width 0 height 3 }", 2, 15, {"'width'", "found '0'"});
  expectError(camera + "image { width 99999999999999999999 height 3 }", 2, 15, {"'width'"});
  expectError(camera + "image { width 1e3 height 3 }", 2, 15, {"whole number", "'1e3'"});
  expectError(camera + "image { width 32768 height 16384 }", 2, 28,
              {"image too large", "32768 x 16384 = 536870912 pixels", "268435456"});
  expectError(camera + "image { height 16384 width 32768 }", 2, 28, {"image too large"});
}

TEST(SceneErrors, OutputExtension) {
  const std::string camera = "camera { eye 0 0 -5 look_at 0 0 0 }\n";
  expectError(camera + "image { width 4 height 3 output \"fig.tga\" }", 2, 33,
              {"'output' must be a file name ending in .png, .ppm, .pfm", "\"fig.tga\""});
  expectError(camera + "image { width 4 height 3 output \"\" }", 2, 33, {".png, .ppm, .pfm"});
  expectError(camera + "image { width 4 height 3 output \"png\" }", 2, 33, {".png, .ppm, .pfm"});
}

TEST(SceneErrors, MissingRequiredParametersAreReportedAtTheBlock) {
  expectBodyError("  sphere { center 0 0 0 }", 3,
                  {"the 'sphere' block is missing 'radius'", "required: center, radius"});
  expectBodyError("light point { color 1 1 1 }", 7,
                  {"the 'light point' block is missing 'position'"});
  expectBodyError("light rect { corner 0 0 0 edge1 1 0 0 }", 7, {"missing 'edge2'"});
  expectBodyError("box { max 1 1 1 }", 1, {"'box' block is missing 'min'"});
  expectBodyError("plane { point 0 0 0 }", 1, {"missing 'normal'"});
  expectError("camera { eye 0 0 -5 }\nimage { width 4 height 3 }", 1, 1,
              {"'camera' block is missing 'look_at'"});
  expectError("camera { eye 0 0 -5 look_at 0 0 0 }\nimage { width 4 }", 2, 1,
              {"'image' block is missing 'height'"});
}

TEST(SceneErrors, MissingCameraOrImageBlock) {
  for (const auto& [text, block] :
       {std::pair{std::string("image { width 4 height 3 }"), std::string("camera")},
        std::pair{std::string("camera { eye 0 0 -5 look_at 0 0 0 }"), std::string("image")},
        std::pair{std::string("# nothing"), std::string("camera")}}) {
    const InputError error = errorOf(text);
    EXPECT_EQ(error.where().file, "bad.scene");
    EXPECT_EQ(error.where().line, 0);
    EXPECT_NE(std::string(error.what()).find("the scene has no " + block + " block"),
              std::string::npos)
        << error.what();
  }
}

TEST(SceneErrors, PlaneNormalMustNotBeZero) {
  expectBodyError("plane { point 0 0 0 normal 0 0 0 }", 28, {"'normal' must not be zero"});
  expectBodyError("plane { point 0 0 0 normal 0 1e-300 0 }", 28, {"'normal' must not be zero"});
}

TEST(SceneErrors, RectLightMustHaveArea) {
  expectBodyError("light rect { corner 0 0 0 edge1 1 0 0 edge2 2 0 0 }", 45,
                  {"'edge1' and 'edge2' are parallel"});
}

TEST(SceneErrors, UnknownKindOfLight) {
  expectBodyError("light spotlight { position 0 0 0 }", 7,
                  {"unknown kind of light 'spotlight'; valid kinds: point, sphere, rect, spot, "
                   "directional"});
  expectBodyError("light pont { position 0 0 0 }", 7, {"(did you mean 'point'?)"});
  expectBodyError("light { position 0 0 0 }", 7, {"expected the kind of light"});
}

TEST(SceneErrors, MissingOpeningBrace) {
  expectBodyError("sphere center 0 0 0 radius 1 }", 8,
                  {"expected '{' to start the 'sphere' block", "found 'center'"});
}

TEST(SceneErrors, UnexpectedEndOfFile) {
  expectError(
      kErrorPreamble + "sphere { center 0 0 0\n   radius 1  \n# the end\n", 4, 12,
      {"unexpected end of file", "'sphere' block opened at line 3, column 8", "no closing '}'"});
  expectBodyError("sphere { center 0 0", 20, {"needs 3 numbers", "the end of the file"});
}

TEST(SceneErrors, LexicalErrorsCarryTheFileName) {
  expectBodyError("sphere { center 0 0 0 radius 1 surface { color 1; } }", 48,
                  {"malformed number '1;'"});
  expectError(kErrorPreamble + "image { output \"abc }", 3, 16, {"unterminated string"});
}

TEST(SceneErrors, FormatShowsTheLineAndACaret) {
  const InputError error = errorOf(kErrorPreamble + "  sphere { center 0 0 0 radius -1 }");
  EXPECT_EQ(error.format(),
            "bad.scene:3:32: error: 'radius' must be in (0, 1e+09], found -1\n"
            "    sphere { center 0 0 0 radius -1 }\n"
            "                                 ^");
}

TEST(SceneErrors, LongLinesAndTokensAreShownCutAroundTheCulprit) {
  const std::string padding(5000, ' ');
  const std::string name(3000, 'x');
  const InputError error =
      errorOf(kErrorPreamble + "sphere {" + padding + name + " radius 1 }" + padding + "# end");
  const std::string text = error.format();
  EXPECT_LT(text.size(), 600u) << text;
  EXPECT_NE(text.find("unknown parameter 'xxxxxxxxxx"), std::string::npos) << text;
  EXPECT_NE(text.find("... (3000 characters)"), std::string::npos) << text;
  // The shown piece of the line starts with "..." and the caret stands under the name.
  const size_t lineStart = text.find("\n  ...") + 1;
  const size_t caretLine = text.find('\n', lineStart) + 1;
  const size_t caret = text.find('^', caretLine);
  ASSERT_NE(caret, std::string::npos) << text;
  EXPECT_EQ(text[lineStart + (caret - caretLine)], 'x') << text;
  EXPECT_EQ(text[lineStart + (caret - caretLine) - 1], ' ') << text;
}

}  // namespace
}  // namespace prt
