textures/base/wall
{
	qer_editorimage textures/base/wall.tga
	surfaceparm nomarks
	{
		map $lightmap
		rgbGen identity
	}
	{
		map textures/base/wall.tga
		blendFunc GL_DST_COLOR GL_ZERO
	}
}
